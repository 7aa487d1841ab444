#include "fullsim/common/hdf5_file.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <type_traits>

namespace feedflow {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "hid_t is stored as std::int64_t");

// Closes an HDF5 handle at the end of a scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) {}
  ~Handle() {
    if (id_ >= 0) closer_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*closer_)(hid_t);
};

std::vector<hsize_t> to_hsize(const std::vector<std::size_t>& dims) {
  return std::vector<hsize_t>(dims.begin(), dims.end());
}

std::string dims_text(const std::vector<std::size_t>& dims) {
  std::string s;
  for (std::size_t d : dims) s += (s.empty() ? "" : " x ") + std::to_string(d);
  return s.empty() ? "scalar" : s;
}

}  // namespace

Hdf5File::Hdf5File(std::filesystem::path path, Mode mode) : path_(std::move(path)) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr dumps
  const std::string name = path_.string();
  if (mode == Mode::read) {
    if (!std::filesystem::exists(path_)) fail("no such file");
    file_ = H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) fail("not a readable HDF5 file (truncated or damaged?)");
    return;
  }
  if (mode == Mode::append && std::filesystem::exists(path_)) {
    file_ = H5Fopen(name.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    if (file_ < 0) fail("cannot open for appending (truncated or damaged?)");
    return;
  }
  if (mode == Mode::scratch) {
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    H5Pset_fapl_core(access.get(), 1 << 20, false);  // grows by 1 MiB, no backing store
    file_ = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
    if (file_ < 0) fail("cannot create in memory");
    return;
  }
  std::error_code ec;
  if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path(), ec);
  // The 1.10 file format: object headers, B-trees and the superblock carry checksums, so a damaged
  // file is an error when read, not silently different data (ParaView 5.x reads this format).
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_libver_bounds(access.get(), H5F_LIBVER_V110, H5F_LIBVER_V110);
  file_ = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
  if (file_ < 0) fail("cannot create");
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5File::fail(const std::string& what) const {
  throw std::runtime_error("HDF5 file " + path_.string() + ": " + what);
}

void Hdf5File::flush() {
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) fail("flush failed");
}

void Hdf5File::close() {
  if (file_ < 0) return;
  const herr_t status = H5Fclose(file_);
  file_ = -1;
  if (status < 0) fail("close failed");
}

bool Hdf5File::exists(const std::string& object) const {
  // Each link along the path must exist before the next one is asked about.
  std::size_t pos = 0;
  while (true) {
    pos = object.find('/', pos + 1);
    const std::string prefix = object.substr(0, pos);
    if (!prefix.empty() && prefix != "/" && H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0)
      return false;
    if (pos == std::string::npos) return true;
  }
}

void Hdf5File::create_group(const std::string& group) {
  Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(links.get(), 1);
  Handle g(H5Gcreate2(file_, group.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.ok()) fail("cannot create group " + group);
}

std::vector<std::string> Hdf5File::members(const std::string& group) const {
  Handle g(H5Gopen2(file_, group.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.ok()) fail("no group " + group);
  H5G_info_t info;
  if (H5Gget_info(g.get(), &info) < 0) fail("cannot list group " + group);
  std::vector<std::string> names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t size = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr,
                                            0, H5P_DEFAULT);
    if (size < 0) fail("cannot list group " + group);
    std::string name(static_cast<std::size_t>(size), '\0');
    H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(),
                       static_cast<std::size_t>(size) + 1, H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}

template <>
std::int64_t Hdf5File::memory_type<double>() { return H5T_NATIVE_DOUBLE; }
template <>
std::int64_t Hdf5File::memory_type<std::uint32_t>() { return H5T_NATIVE_UINT32; }
template <>
std::int64_t Hdf5File::memory_type<std::uint64_t>() { return H5T_NATIVE_UINT64; }
template <>
std::int64_t Hdf5File::memory_type<std::int64_t>() { return H5T_NATIVE_INT64; }
template <>
std::int64_t Hdf5File::memory_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }
template <>
int Hdf5File::type_class<double>() { return H5T_FLOAT; }
template <>
int Hdf5File::type_class<std::uint32_t>() { return H5T_INTEGER; }
template <>
int Hdf5File::type_class<std::uint64_t>() { return H5T_INTEGER; }
template <>
int Hdf5File::type_class<std::int64_t>() { return H5T_INTEGER; }
template <>
int Hdf5File::type_class<std::uint8_t>() { return H5T_INTEGER; }

void Hdf5File::write_raw(const std::string& dataset, std::int64_t memory_type, const void* data,
                         const std::vector<std::size_t>& dims, const std::string& unit) {
  const std::vector<hsize_t> h = to_hsize(dims);
  Handle space(H5Screate_simple(static_cast<int>(h.size()), h.data(), nullptr), H5Sclose);
  if (!space.ok()) fail("cannot describe dataset " + dataset + " of " + dims_text(dims));
  Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(links.get(), 1);
  std::size_t count = 1;
  for (std::size_t d : dims) count *= d;
  // Every non-empty array is one chunk with a Fletcher-32 checksum: a damaged value fails the read.
  Handle creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (count > 0 && !h.empty()) {
    H5Pset_chunk(creation.get(), static_cast<int>(h.size()), h.data());
    H5Pset_fletcher32(creation.get());
  }
  Handle set(H5Dcreate2(file_, dataset.c_str(), memory_type, space.get(), links.get(), creation.get(),
                        H5P_DEFAULT),
             H5Dclose);
  if (!set.ok()) fail("cannot create dataset " + dataset);
  if (count > 0 &&
      H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("cannot write dataset " + dataset);
  if (!unit.empty()) set_attribute(dataset, "unit", unit);
}

template <class T>
void Hdf5File::write(const std::string& dataset, const std::vector<T>& data,
                     const std::vector<std::size_t>& dims, const std::string& unit) {
  std::size_t count = 1;
  for (std::size_t d : dims) count *= d;
  if (count != data.size())
    fail("dataset " + dataset + ": " + std::to_string(data.size()) + " values for " +
         dims_text(dims));
  write_raw(dataset, memory_type<T>(), data.data(), dims, unit);
}

void Hdf5File::write(const std::string& dataset, const double* data,
                     const std::vector<std::size_t>& dims, const std::string& unit) {
  write_raw(dataset, memory_type<double>(), data, dims, unit);
}

std::vector<std::size_t> Hdf5File::dims(const std::string& dataset) const {
  Handle set(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail("no dataset " + dataset);
  Handle space(H5Dget_space(set.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail("cannot read the shape of " + dataset);
  std::vector<hsize_t> h(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), h.data(), nullptr);
  return std::vector<std::size_t>(h.begin(), h.end());
}

void Hdf5File::read_raw(const std::string& dataset, std::int64_t memory_type, int type_class,
                        void* data, std::size_t count,
                        const std::vector<std::size_t>& expected_dims) const {
  Handle set(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail("no dataset " + dataset);
  Handle type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) != type_class) fail("dataset " + dataset + " has another type");
  if (count > 0 && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("cannot read dataset " + dataset + " (damaged: its checksum does not match?)");
  (void)expected_dims;
}

template <class T>
std::vector<T> Hdf5File::read(const std::string& dataset,
                              const std::vector<std::size_t>& expected_dims) const {
  const std::vector<std::size_t> d = dims(dataset);
  if (!expected_dims.empty() && d != expected_dims)
    fail("dataset " + dataset + " is " + dims_text(d) + ", expected " + dims_text(expected_dims));
  std::size_t count = 1;
  for (std::size_t k : d) count *= k;
  std::vector<T> out(count);
  read_raw(dataset, memory_type<T>(), type_class<T>(), out.data(), count, expected_dims);
  return out;
}

template void Hdf5File::write(const std::string&, const std::vector<double>&,
                              const std::vector<std::size_t>&, const std::string&);
template void Hdf5File::write(const std::string&, const std::vector<std::uint32_t>&,
                              const std::vector<std::size_t>&, const std::string&);
template void Hdf5File::write(const std::string&, const std::vector<std::uint64_t>&,
                              const std::vector<std::size_t>&, const std::string&);
template void Hdf5File::write(const std::string&, const std::vector<std::int64_t>&,
                              const std::vector<std::size_t>&, const std::string&);
template void Hdf5File::write(const std::string&, const std::vector<std::uint8_t>&,
                              const std::vector<std::size_t>&, const std::string&);
template std::vector<double> Hdf5File::read(const std::string&,
                                            const std::vector<std::size_t>&) const;
template std::vector<std::uint32_t> Hdf5File::read(const std::string&,
                                                   const std::vector<std::size_t>&) const;
template std::vector<std::uint64_t> Hdf5File::read(const std::string&,
                                                   const std::vector<std::size_t>&) const;
template std::vector<std::int64_t> Hdf5File::read(const std::string&,
                                                  const std::vector<std::size_t>&) const;
template std::vector<std::uint8_t> Hdf5File::read(const std::string&,
                                                  const std::vector<std::size_t>&) const;

namespace {

// Opens a group or dataset by path.
hid_t open_object(hid_t file, const std::string& object) {
  return H5Oopen(file, object.c_str(), H5P_DEFAULT);
}

}  // namespace

void Hdf5File::set_attribute(const std::string& object, const std::string& name, double value) {
  Handle o(open_object(file_, object), H5Oclose);
  if (!o.ok()) fail("no object " + object);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle a(H5Acreate2(o.get(), name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Aclose);
  if (!a.ok() || H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail("cannot write attribute " + object + "@" + name);
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             std::int64_t value) {
  Handle o(open_object(file_, object), H5Oclose);
  if (!o.ok()) fail("no object " + object);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle a(H5Acreate2(o.get(), name.c_str(), H5T_NATIVE_INT64, space.get(), H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Aclose);
  if (!a.ok() || H5Awrite(a.get(), H5T_NATIVE_INT64, &value) < 0)
    fail("cannot write attribute " + object + "@" + name);
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             const std::string& value) {
  Handle o(open_object(file_, object), H5Oclose);
  if (!o.ok()) fail("no object " + object);
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), value.empty() ? 1 : value.size());
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle a(H5Acreate2(o.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  const std::string stored = value.empty() ? std::string(1, '\0') : value;
  if (!a.ok() || H5Awrite(a.get(), type.get(), stored.data()) < 0)
    fail("cannot write attribute " + object + "@" + name);
}

double Hdf5File::double_attribute(const std::string& object, const std::string& name) const {
  Handle a(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  if (!a.ok()) fail("no attribute " + object + "@" + name);
  double v = 0.0;
  if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0)
    fail("cannot read attribute " + object + "@" + name);
  return v;
}

std::int64_t Hdf5File::integer_attribute(const std::string& object,
                                         const std::string& name) const {
  Handle a(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  if (!a.ok()) fail("no attribute " + object + "@" + name);
  std::int64_t v = 0;
  if (H5Aread(a.get(), H5T_NATIVE_INT64, &v) < 0)
    fail("cannot read attribute " + object + "@" + name);
  return v;
}

std::string Hdf5File::string_attribute(const std::string& object, const std::string& name) const {
  Handle a(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  if (!a.ok()) fail("no attribute " + object + "@" + name);
  Handle type(H5Aget_type(a.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) fail("attribute " + object + "@" + name + " is not text");
  const std::size_t size = H5Tget_size(type.get());
  std::string s(size, '\0');
  if (H5Aread(a.get(), type.get(), s.data()) < 0)
    fail("cannot read attribute " + object + "@" + name);
  s.resize(s.find('\0') == std::string::npos ? s.size() : s.find('\0'));
  return s;
}

}  // namespace feedflow
