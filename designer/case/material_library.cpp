#include "designer/case/material_library.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "designer/case/material_reader.hpp"
#include "designer/case/toml_text.hpp"
#include "models/core/errors.hpp"
#include "models/material/builtin_materials.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

std::string read_file(const fs::path& path) {
  return read_input_file(path.string(), "material file");
}

std::string description_of(const toml::table& table) {
  if (const auto* d = table.get("description"); d && d->is_string()) return d->as_string()->get();
  return "";
}

}  // namespace

MaterialLibrary::MaterialLibrary(std::vector<fs::path> folders) : folders_(std::move(folders)) {}

MaterialLibrary MaterialLibrary::standard(const fs::path& case_folder) {
  std::vector<fs::path> folders;
  if (!case_folder.empty()) folders.push_back(case_folder / "materials");
  folders.push_back(fs::path("cases") / "materials");
  if (const char* env = std::getenv("FEEDFLOW_MATERIALS")) {
    std::stringstream list(env);
    for (std::string item; std::getline(list, item, ':');)
      if (!item.empty()) folders.emplace_back(item);
  }
  // The same folder reached twice (the case lives in ./cases) is searched once.
  std::vector<fs::path> unique;
  for (const auto& f : folders) {
    std::error_code ec;
    const auto canonical = fs::weakly_canonical(f, ec);
    const auto& key = ec ? f : canonical;
    if (std::none_of(unique.begin(), unique.end(), [&](const fs::path& u) {
          std::error_code ec2;
          return fs::weakly_canonical(u, ec2) == key;
        }))
      unique.push_back(f.lexically_normal());
  }
  return MaterialLibrary(std::move(unique));
}

std::vector<MaterialEntry> MaterialLibrary::list() const {
  std::vector<MaterialEntry> entries;
  auto add = [&](MaterialEntry e) {
    if (std::none_of(entries.begin(), entries.end(),
                     [&](const MaterialEntry& x) { return x.name == e.name; }))
      entries.push_back(std::move(e));
  };
  for (const auto& folder : folders_) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& item : fs::directory_iterator(folder, ec))
      if (item.path().extension() == ".toml") files.push_back(item.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      std::string description;
      try {
        description = description_of(parse_material_text(read_file(file), file.string()));
      } catch (const InputError& e) {
        description = std::string("(unreadable: ") + e.what() + ")";
      }
      add({file.stem().string(), file.string(), description});
    }
  }
  for (const auto& builtin : builtin_material_texts())
    add({std::string(builtin.name), "built-in",
         description_of(parse_material_text(builtin.toml, "built-in"))});
  return entries;
}

bool MaterialLibrary::contains(const std::string& name) const {
  const auto entries = list();
  return std::any_of(entries.begin(), entries.end(),
                     [&](const MaterialEntry& e) { return e.name == name; });
}

Material MaterialLibrary::load(const std::string& name) const {
  {
    const std::lock_guard<std::mutex> lock(loaded_->mutex);
    if (const auto it = loaded_->by_name.find(name); it != loaded_->by_name.end())
      return it->second;
  }
  Material m = read(name);
  const std::lock_guard<std::mutex> lock(loaded_->mutex);
  return loaded_->by_name.emplace(name, std::move(m)).first->second;
}

Material MaterialLibrary::read(const std::string& name) const {
  for (const auto& folder : folders_) {
    const fs::path file = folder / (name + ".toml");
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(file, ec))) continue;
    // An entry that is there but is no readable file (a folder, a broken link) is an error, not
    // a reason to fall back silently on a material of the same name elsewhere.
    const auto table = parse_material_text(read_file(file), file.string());
    Material m = read_material(table, file.string(), "material file " + file.string());
    if (m.name != name)
      throw InputError(file.string(), "name",
                       "the file " + file.filename().string() + " declares the material \"" + m.name +
                           "\"; a material file is named after its material (" + m.name + ".toml), or give it "
                           "name = \"" + name + "\"");
    m.origin = file.string();
    return m;
  }
  for (const auto& builtin : builtin_material_texts()) {
    if (builtin.name != name) continue;
    const std::string path = "built-in:" + std::string(builtin.name) + ".toml";
    Material m = read_material(parse_material_text(builtin.toml, path), path, "built-in material");
    m.origin = "built-in";
    return m;
  }
  std::string known, searched;
  for (const auto& e : list()) known += (known.empty() ? "" : ", ") + e.name;
  for (const auto& folder : folders_) searched += (searched.empty() ? "" : ", ") + folder.string() + "/";
  throw InputError("", "", "no material named \"" + name + "\" in " +
                               (searched.empty() ? std::string() : searched + " or ") +
                               "the built-in materials (known: " + known +
                               "; more folders: FEEDFLOW_MATERIALS=dir1:dir2)");
}

}  // namespace feedflow
