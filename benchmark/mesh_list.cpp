#include "mesh_list.h"

#include <set>
#include <system_error>

namespace cut_benchmark {

bool is_file(const fs::path& p)
{
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

fs::path find_mesh(const fs::path& dir, const std::string& name)
{
  const fs::path given(name);
  if(stem_of(name) != given.filename().string()) // has a mesh extension
  {
    if(given.is_absolute() && is_file(given)) return given;
    if(is_file(dir / given)) return dir / given;
    if(is_file(given)) return given;
  }
  for(const char* sub : {"uvat", "optcuts", ""})
  {
    const fs::path p = dir / sub / (name + ".obj");
    if(is_file(p)) return p;
  }
  return {};
}

std::vector<Mesh_entry> mesh_list(const Options& opt, const std::vector<std::string>& default_names,
                                  std::vector<std::string>& missing)
{
  std::vector<Mesh_entry> list;
  std::set<std::string> seen;
  auto add = [&](const std::string& name, bool keep_missing) {
    const fs::path file = find_mesh(opt.mesh_dir, name);
    const std::string stem = stem_of(name);
    if(seen.count(stem)) return;
    seen.insert(stem);
    if(file.empty())
    {
      missing.push_back(name);
      if(!keep_missing) return;
    }
    list.push_back({stem, file});
  };
  if(!opt.meshes.empty())
  {
    for(const auto& name : opt.meshes) add(name, true);
    return list;
  }
  for(const auto& name : default_names) add(name, false);
  return list;
}

std::vector<Mesh_entry> mesh_list(const Options& opt, const References& refs,
                                  std::vector<std::string>& missing)
{
  std::vector<std::string> names = refs.measured_order;
  names.insert(names.end(), refs.paper_files.begin(), refs.paper_files.end());
  return mesh_list(opt, names, missing);
}

std::string relative_file(const Mesh_entry& entry, const fs::path& mesh_dir)
{
  return entry.file.empty() ? std::string() : entry.file.lexically_relative(mesh_dir).generic_string();
}

} // namespace cut_benchmark
