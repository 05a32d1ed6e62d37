// What the tests of uv_unwrap's command line share: running the program on a
// file with --stats, and checking that its statistics report a valid atlas.
// Header-only, for the test programs of tools/ (GoogleTest, nlohmann/json).
#ifndef CUT_PARAM_TOOLS_TESTS_UV_UNWRAP_RUNS_H
#define CUT_PARAM_TOOLS_TESTS_UV_UNWRAP_RUNS_H

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>

namespace uv_unwrap_test {

/// The exit status of a shell command, or -1 if it did not exit.
inline int exit_status(const std::string& command)
{
  const int status = std::system(command.c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// One run of uv_unwrap: its exit status and its statistics (discarded JSON
/// when it wrote none).
struct Unwrap_run
{
  int exit_status = -1;
  nlohmann::json stats;
};

/// Runs `program` on `input` quietly, writing `output` and the statistics
/// next to it (OUTPUT.json), with `extra` arguments appended.
inline Unwrap_run run_uv_unwrap(const std::string& program, const std::filesystem::path& input,
                                const std::filesystem::path& output, const std::string& extra = "")
{
  const std::filesystem::path stats = output.string() + ".json";
  std::filesystem::remove(stats);
  Unwrap_run r;
  r.exit_status = exit_status("\"" + program + "\" \"" + input.string() + "\" -q -o \"" + output.string() +
                              "\" --stats \"" + stats.string() + "\"" + (extra.empty() ? "" : " " + extra));
  std::ifstream in(stats);
  r.stats = nlohmann::json::parse(in, nullptr, false);
  return r;
}

/// True if a warning of `stats` holds `text`.
inline bool has_warning(const nlohmann::json& stats, const std::string& text)
{
  if(!stats.is_object() || !stats.contains("warnings")) return false;
  for(const auto& w : stats["warnings"])
    if(w.get<std::string>().find(text) != std::string::npos) return true;
  return false;
}

/// Checks that `r` unwrapped `what`: exit 0, status ok, no flipped face, no
/// border crossing, every UV in the unit square, and (if not empty) a warning
/// holding `warning`. Returns false (after the failure) when there is no
/// result to check further.
inline bool expect_valid_atlas(const Unwrap_run& r, const std::string& what, const std::string& warning = "")
{
  if(r.stats.is_discarded())
  {
    ADD_FAILURE() << what << ": no statistics";
    return false;
  }
  EXPECT_EQ(r.exit_status, 0) << what << ": " << r.stats.dump();
  if(r.stats["status"] != "ok")
  {
    ADD_FAILURE() << what << ": " << r.stats.dump();
    return false;
  }
  EXPECT_EQ(r.stats["flipped_faces"], 0) << what;
  EXPECT_EQ(r.stats["border_crossings"], 0) << what;
  EXPECT_EQ(r.stats["uv_in_unit_square"], true) << what;
  if(!warning.empty())
  {
    EXPECT_TRUE(has_warning(r.stats, warning))
      << what << ": no warning with '" << warning << "': " << r.stats["warnings"].dump();
  }
  return true;
}

} // namespace uv_unwrap_test

#endif
