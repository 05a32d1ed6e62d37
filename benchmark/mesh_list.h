// The meshes of a comparison: those named on the command line, or every mesh
// of its reference tables found in the mesh folder.
#ifndef CUT_PARAM_BENCHMARK_MESH_LIST_H
#define CUT_PARAM_BENCHMARK_MESH_LIST_H

#include "options.h"
#include "reference_tables.h"

#include <filesystem>
#include <string>
#include <vector>

namespace cut_benchmark {

struct Mesh_entry
{
  std::string name;   // file stem
  fs::path file;      // empty if not found
};

bool is_file(const fs::path& p);

/// A name is looked up as given (relative to the mesh folder, or absolute),
/// then as <name>.obj in uvat/, optcuts/ and the folder itself. Empty if not found.
fs::path find_mesh(const fs::path& dir, const std::string& name);

/// The meshes to run, each name once: those of --meshes, else `default_names`.
/// Names without a file go to `missing`; they stay in the list (as not found)
/// only when named with --meshes.
std::vector<Mesh_entry> mesh_list(const Options& opt, const std::vector<std::string>& default_names,
                                  std::vector<std::string>& missing);

/// mesh_list() with the meshes of both tables of `refs` by default.
std::vector<Mesh_entry> mesh_list(const Options& opt, const References& refs,
                                  std::vector<std::string>& missing);

/// The mesh's file relative to the mesh folder, with '/' ("" if not found).
std::string relative_file(const Mesh_entry& entry, const fs::path& mesh_dir);

} // namespace cut_benchmark

#endif
