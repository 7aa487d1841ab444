#pragma once
// An HDF5 file through the serial C API, for outputs and checkpoints: groups, typed datasets
// (double, 32- and 64-bit unsigned and signed integers, bytes) of one or two dimensions with a
// "unit" attribute, and scalar attributes. Every failure throws std::runtime_error naming the
// file and the object, so a damaged or foreign file is refused with a readable message.
//
//   Hdf5File f("run/particles.h5", Hdf5File::Mode::append);
//   f.create_group("/snapshots/step_000100");
//   f.write("/snapshots/step_000100/radius", radius, {radius.size()}, "m");
//   f.close();  // flushes and reports errors (the destructor closes silently)
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace feedflow {

class Hdf5File {
 public:
  // create truncates; append creates if missing; scratch: a new file in memory only (written to
  // and dropped, nothing on disk; its path only names it).
  enum class Mode { create, append, read, scratch };

  Hdf5File(std::filesystem::path path, Mode mode);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Writes the buffers to disk (the file stays open).
  void flush();
  // Closes the file; throws when HDF5 reports an error on the way.
  void close();

  bool exists(const std::string& object) const;
  // Creates the group and any missing parents.
  void create_group(const std::string& group);
  // The names in a group, in the order HDF5 lists them (by name).
  std::vector<std::string> members(const std::string& group) const;

  // A dataset of `dims` (one or two dimensions; their product is data.size()).
  template <class T>
  void write(const std::string& dataset, const std::vector<T>& data,
             const std::vector<std::size_t>& dims, const std::string& unit);
  void write(const std::string& dataset, const double* data, const std::vector<std::size_t>& dims,
             const std::string& unit);
  // Reads a whole dataset; throws when it is missing, has another type class or other dims
  // than `expected_dims` (when given).
  template <class T>
  std::vector<T> read(const std::string& dataset,
                      const std::vector<std::size_t>& expected_dims = {}) const;
  std::vector<std::size_t> dims(const std::string& dataset) const;

  // Scalar attributes on a group or dataset.
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, std::int64_t value);
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  double double_attribute(const std::string& object, const std::string& name) const;
  std::int64_t integer_attribute(const std::string& object, const std::string& name) const;
  std::string string_attribute(const std::string& object, const std::string& name) const;

 private:
  [[noreturn]] void fail(const std::string& what) const;
  void write_raw(const std::string& dataset, std::int64_t memory_type, const void* data,
                 const std::vector<std::size_t>& dims, const std::string& unit);
  void read_raw(const std::string& dataset, std::int64_t memory_type, int type_class, void* data,
                std::size_t count, const std::vector<std::size_t>& expected_dims) const;
  template <class T>
  static std::int64_t memory_type();
  template <class T>
  static int type_class();

  std::filesystem::path path_;
  std::int64_t file_ = -1;
};

}  // namespace feedflow
