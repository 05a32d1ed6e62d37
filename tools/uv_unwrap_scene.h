// uv_unwrap --atlas: every input unwrapped as without it (its meshes kept as
// the parts of a scene, its writing put off), then one atlas packed for all
// (scene_atlas_run.h), then every input written; the statistics of each
// input (JSON Lines, --stats) get its meshes' pages; --svg draws every page.
#ifndef CUT_PARAM_TOOLS_UV_UNWRAP_SCENE_H
#define CUT_PARAM_TOOLS_UV_UNWRAP_SCENE_H

#include "scene_atlas_run.h"
#include "uv_unwrap_options.h"

#include <csignal>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace uv_unwrap {

/// Unwraps one input into the scene (its parts and its writer added), every failure in the summary.
using Unwrap_input = std::function<Run_summary(const std::string& input, Scene* scene)>;

/// Runs the scene; returns the number of inputs that failed. `interrupted`: set on Ctrl-C.
int run_scene(const Options& options, const std::vector<std::string>& inputs, std::ostream* jsonl,
              const Unwrap_input& unwrap_one, const volatile std::sig_atomic_t& interrupted);

} // namespace uv_unwrap

#endif
