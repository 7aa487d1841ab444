#include "models/os/shared_library.hpp"

#include <dlfcn.h>

#include "models/core/errors.hpp"

namespace feedflow {

SharedLibrary::SharedLibrary(std::initializer_list<const char*> names, std::string package,
                             std::string purpose)
    : package_(std::move(package)), purpose_(std::move(purpose)) {
  std::string errors;
  for (const char* name : names) {
    if (name_.empty()) name_ = name;
    handle_ = ::dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (handle_ != nullptr) return;
    const char* error = ::dlerror();
    errors += (errors.empty() ? "" : "; ") + std::string(error != nullptr ? error : name);
  }
  throw NotAvailable(purpose_ + " needs " + name_ + " (Debian package " + package_ +
                     "), which could not be loaded: " + errors);
}

void* SharedLibrary::symbol(const char* name) const {
  ::dlerror();
  void* address = ::dlsym(handle_, name);
  if (address == nullptr)
    throw NotAvailable(purpose_ + " needs " + std::string(name) + " from " + name_ +
                       " (Debian package " + package_ + "), which does not provide it");
  return address;
}

}  // namespace feedflow
