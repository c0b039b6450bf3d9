#include "deploydyn/util/optional_module.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

// Set by CMakeLists.txt on this file alone (paths of the build and of the install).
#ifndef DEPLOYDYN_MODULE_BUILD_DIR
#error "DEPLOYDYN_MODULE_BUILD_DIR must be defined (CMakeLists.txt)"
#endif

namespace deploydyn {
namespace {

std::vector<std::filesystem::path> module_folders() {
  // Set, it is the only place: a user (or a test) says exactly which modules to use.
  if (const char* dir = std::getenv("DEPLOYDYN_MODULE_DIR"); dir != nullptr && *dir != '\0') return {dir};
  std::vector<std::filesystem::path> folders;
  // The object (program or shared library) this code was linked into.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&module_folders), &info) != 0 && info.dli_fname != nullptr) {
    std::error_code error;
    const std::filesystem::path object = std::filesystem::canonical(info.dli_fname, error);
    if (!error) folders.push_back((object.parent_path() / DEPLOYDYN_MODULE_RELATIVE_DIR).lexically_normal());
  }
  folders.emplace_back(DEPLOYDYN_MODULE_INSTALL_DIR);
  folders.emplace_back(DEPLOYDYN_MODULE_BUILD_DIR);
  return folders;
}

}  // namespace

std::string optional_module_folders() {
  std::string list;
  for (const auto& folder : module_folders()) list += (list.empty() ? "" : ", ") + folder.lexically_normal().string();
  return list;
}

void* optional_module_symbol(std::string_view name, const char* symbol, std::string_view needed_for) {
  // dlopen is thread-safe, but one message per failure reads better than interleaved ones.
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  const std::string file = std::string(name) + ".so";
  std::string reasons;
  for (const auto& folder : module_folders()) {
    const std::filesystem::path path = folder / file;
    std::error_code error;
    if (!std::filesystem::exists(path, error)) continue;
    // RTLD_LOCAL: a module's symbols (and its copy of the library's code) stay its own.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      reasons += std::string("; ") + dlerror();
      continue;
    }
    if (void* address = dlsym(handle, symbol); address != nullptr) return address;
    reasons += "; " + path.string() + " has no " + symbol + " (a module of another deploydyn build?)";
  }
  throw std::runtime_error("the module " + file + " could not be loaded (looked in " + optional_module_folders() +
                           (reasons.empty() ? "; not found" : reasons) + "); it is needed for " +
                           std::string(needed_for) +
                           "; build and install it with deploydyn, or point DEPLOYDYN_MODULE_DIR to its folder");
}

}  // namespace deploydyn
