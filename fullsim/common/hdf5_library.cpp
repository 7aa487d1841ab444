// HDF5, loaded when the first HDF5 file is opened instead of at program start: Debian's
// libhdf5_serial pulls in libcurl and through it TLS, Kerberos and LDAP libraries, two thirds of
// the start-up time of a command that writes no HDF5 (`feedflow design`, `version`). The
// program does not link libhdf5; the HDF5 functions used by hdf5_file.cpp (and the tests) are
// defined here as forwarders (see models/os/shared_library.hpp). A call to an HDF5 function not
// listed here fails to link: add it below (the compiler checks the signature against hdf5.h).
#include <hdf5.h>

#include <vector>

#include "models/os/shared_library.hpp"

namespace {

const feedflow::SharedLibrary& hdf5_library() {
  static const feedflow::SharedLibrary library(
      {"libhdf5_serial.so.103", "libhdf5_serial.so"}, "libhdf5-103-1",
      "writing and reading HDF5 files (snapshots, checkpoints)");
  return library;
}

// HDF5's predefined type and property-list ids are variables that H5open() sets. The header
// macros (H5T_NATIVE_DOUBLE, ...) call H5open() and then read the variable, so the forwarding
// H5open below copies the library's values into the program's variables of the same name.
struct IdVariable {
  hid_t* program;
  const char* name;
};

}  // namespace

hid_t H5T_NATIVE_DOUBLE_g = -1;
hid_t H5T_NATIVE_UINT8_g = -1;
hid_t H5T_NATIVE_UINT32_g = -1;
hid_t H5T_NATIVE_UINT64_g = -1;
hid_t H5T_NATIVE_INT64_g = -1;
hid_t H5T_C_S1_g = -1;
hid_t H5P_CLS_LINK_CREATE_ID_g = -1;
hid_t H5P_CLS_FILE_ACCESS_ID_g = -1;
hid_t H5P_CLS_DATASET_CREATE_ID_g = -1;

extern "C" herr_t H5open(void) {
  static const IdVariable kVariables[] = {
      {&H5T_NATIVE_DOUBLE_g, "H5T_NATIVE_DOUBLE_g"},
      {&H5T_NATIVE_UINT8_g, "H5T_NATIVE_UINT8_g"},
      {&H5T_NATIVE_UINT32_g, "H5T_NATIVE_UINT32_g"},
      {&H5T_NATIVE_UINT64_g, "H5T_NATIVE_UINT64_g"},
      {&H5T_NATIVE_INT64_g, "H5T_NATIVE_INT64_g"},
      {&H5T_C_S1_g, "H5T_C_S1_g"},
      {&H5P_CLS_LINK_CREATE_ID_g, "H5P_CLS_LINK_CREATE_ID_g"},
      {&H5P_CLS_FILE_ACCESS_ID_g, "H5P_CLS_FILE_ACCESS_ID_g"},
      {&H5P_CLS_DATASET_CREATE_ID_g, "H5P_CLS_DATASET_CREATE_ID_g"},
  };
  static const auto open = reinterpret_cast<decltype(&::H5open)>(hdf5_library().symbol("H5open"));
  static const auto library_ids = [] {
    std::vector<const hid_t*> ids;
    for (const IdVariable& v : kVariables)
      ids.push_back(static_cast<const hid_t*>(hdf5_library().symbol(v.name)));
    return ids;
  }();
  const herr_t status = open();
  for (std::size_t k = 0; k < library_ids.size(); ++k) *kVariables[k].program = *library_ids[k];
  return status;
}

FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Aclose, (hid_t attr_id), (attr_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Acreate2,
                 (hid_t loc_id, const char* attr_name, hid_t type_id, hid_t space_id, hid_t acpl_id,
                  hid_t aapl_id),
                 (loc_id, attr_name, type_id, space_id, acpl_id, aapl_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Aget_type, (hid_t attr_id), (attr_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Aopen,
                 (hid_t obj_id, const char* attr_name, hid_t aapl_id), (obj_id, attr_name, aapl_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Aopen_by_name,
                 (hid_t loc_id, const char* obj_name, const char* attr_name, hid_t aapl_id,
                  hid_t lapl_id),
                 (loc_id, obj_name, attr_name, aapl_id, lapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Aread, (hid_t attr_id, hid_t type_id, void* buf),
                 (attr_id, type_id, buf))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Awrite, (hid_t attr_id, hid_t type_id, const void* buf),
                 (attr_id, type_id, buf))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Dclose, (hid_t dset_id), (dset_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Dcreate2,
                 (hid_t loc_id, const char* name, hid_t type_id, hid_t space_id, hid_t lcpl_id,
                  hid_t dcpl_id, hid_t dapl_id),
                 (loc_id, name, type_id, space_id, lcpl_id, dcpl_id, dapl_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Dget_space, (hid_t dset_id), (dset_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Dget_type, (hid_t dset_id), (dset_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Dopen2, (hid_t loc_id, const char* name, hid_t dapl_id),
                 (loc_id, name, dapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Dread,
                 (hid_t dset_id, hid_t mem_type_id, hid_t mem_space_id, hid_t file_space_id,
                  hid_t dxpl_id, void* buf),
                 (dset_id, mem_type_id, mem_space_id, file_space_id, dxpl_id, buf))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Dwrite,
                 (hid_t dset_id, hid_t mem_type_id, hid_t mem_space_id, hid_t file_space_id,
                  hid_t dxpl_id, const void* buf),
                 (dset_id, mem_type_id, mem_space_id, file_space_id, dxpl_id, buf))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Eset_auto2,
                 (hid_t estack_id, H5E_auto2_t func, void* client_data),
                 (estack_id, func, client_data))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Fclose, (hid_t file_id), (file_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Fcreate,
                 (const char* filename, unsigned flags, hid_t fcpl_id, hid_t fapl_id),
                 (filename, flags, fcpl_id, fapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Fflush, (hid_t object_id, H5F_scope_t scope),
                 (object_id, scope))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Fopen,
                 (const char* filename, unsigned flags, hid_t fapl_id), (filename, flags, fapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Gclose, (hid_t group_id), (group_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Gcreate2,
                 (hid_t loc_id, const char* name, hid_t lcpl_id, hid_t gcpl_id, hid_t gapl_id),
                 (loc_id, name, lcpl_id, gcpl_id, gapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Gget_info, (hid_t loc_id, H5G_info_t* ginfo),
                 (loc_id, ginfo))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Gopen2, (hid_t loc_id, const char* name, hid_t gapl_id),
                 (loc_id, name, gapl_id))
FEEDFLOW_FORWARD(hdf5_library(), htri_t, H5Lexists, (hid_t loc_id, const char* name, hid_t lapl_id),
                 (loc_id, name, lapl_id))
FEEDFLOW_FORWARD(hdf5_library(), ssize_t, H5Lget_name_by_idx,
                 (hid_t loc_id, const char* group_name, H5_index_t idx_type, H5_iter_order_t order,
                  hsize_t n, char* name, size_t size, hid_t lapl_id),
                 (loc_id, group_name, idx_type, order, n, name, size, lapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Oclose, (hid_t object_id), (object_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Oopen, (hid_t loc_id, const char* name, hid_t lapl_id),
                 (loc_id, name, lapl_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Pclose, (hid_t plist_id), (plist_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Pcreate, (hid_t cls_id), (cls_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Pset_chunk, (hid_t plist_id, int ndims, const hsize_t dim[]),
                 (plist_id, ndims, dim))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Pset_fletcher32, (hid_t plist_id), (plist_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Pset_fapl_core,
                 (hid_t fapl_id, size_t increment, hbool_t backing_store),
                 (fapl_id, increment, backing_store))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Pset_libver_bounds,
                 (hid_t plist_id, H5F_libver_t low, H5F_libver_t high), (plist_id, low, high))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Pset_create_intermediate_group,
                 (hid_t plist_id, unsigned crt_intmd), (plist_id, crt_intmd))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Sclose, (hid_t space_id), (space_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Screate, (H5S_class_t type), (type))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Screate_simple,
                 (int rank, const hsize_t dims[], const hsize_t maxdims[]), (rank, dims, maxdims))
FEEDFLOW_FORWARD(hdf5_library(), int, H5Sget_simple_extent_dims,
                 (hid_t space_id, hsize_t dims[], hsize_t maxdims[]), (space_id, dims, maxdims))
FEEDFLOW_FORWARD(hdf5_library(), int, H5Sget_simple_extent_ndims, (hid_t space_id), (space_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Tclose, (hid_t type_id), (type_id))
FEEDFLOW_FORWARD(hdf5_library(), hid_t, H5Tcopy, (hid_t type_id), (type_id))
FEEDFLOW_FORWARD(hdf5_library(), H5T_class_t, H5Tget_class, (hid_t type_id), (type_id))
FEEDFLOW_FORWARD(hdf5_library(), size_t, H5Tget_size, (hid_t type_id), (type_id))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Tset_size, (hid_t type_id, size_t size), (type_id, size))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5Tset_strpad, (hid_t type_id, H5T_str_t strpad),
                 (type_id, strpad))
FEEDFLOW_FORWARD(hdf5_library(), herr_t, H5check_version,
                 (unsigned majnum, unsigned minnum, unsigned relnum), (majnum, minnum, relnum))
