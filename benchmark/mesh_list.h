// The meshes of the comparison: those named on the command line, or every
// mesh of the reference tables found in the mesh folder.
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

/// The meshes to run, each name once. Names without a file go to `missing`;
/// they stay in the list (as not found) only when named with --meshes.
std::vector<Mesh_entry> mesh_list(const Options& opt, const References& refs,
                                  std::vector<std::string>& missing);

} // namespace cut_benchmark

#endif
