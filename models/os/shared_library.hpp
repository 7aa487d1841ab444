#pragma once
// A shared library loaded when first needed (dlopen) instead of at program start. Libraries that
// only some commands use (OSMesa and its libLLVM for rendering, HDF5 and its libcurl for
// simulation output, cairo for plots) would otherwise cost every start, `feedflow version`
// included. The library stays loaded for the rest of the run.
#include <initializer_list>
#include <string>

namespace feedflow {

class SharedLibrary {
 public:
  // Loads the first of `names` (sonames, tried in order) that loads. Throws NotAvailable
  // "<purpose> needs <first name> (Debian package <package>), which could not be loaded: ..."
  // when none does.
  SharedLibrary(std::initializer_list<const char*> names, std::string package, std::string purpose);
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The address of `name` in the library; throws NotAvailable naming it when it is missing.
  void* symbol(const char* name) const;

 private:
  void* handle_ = nullptr;
  std::string name_;
  std::string package_;
  std::string purpose_;
};

}  // namespace feedflow

// Defines the C function `name`, declared by the library's own header, as a forwarder to the
// same function in `library` (an expression giving a const SharedLibrary&), looked up on its
// first call. A program that links the forwarders instead of the library loads the library only
// when one of them is called. `params` is the parameter list with names, `args` the names:
//   FEEDFLOW_FORWARD(cairo(), cairo_status_t, cairo_status, (cairo_t* cr), (cr))
// The compiler checks each signature against the header's declaration.
#define FEEDFLOW_FORWARD(library, result, name, params, args)         \
  extern "C" result name params {                                     \
    static const auto feedflow_forward_target =                       \
        reinterpret_cast<decltype(&::name)>((library).symbol(#name)); \
    return feedflow_forward_target args;                              \
  }
