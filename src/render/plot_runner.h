#pragma once
// Plots of a run folder (mu(t), profiles, energy shares, agglomerate PDFs) are drawn by
// scripts/plot_run.py with matplotlib; `softgrain analyze --plots` finds and runs it.
//
// Where the script is looked for, in order:
//  1. <directory of the running executable>/../share/softgrain/plot_run.py: the installed
//     layout (app/CMakeLists.txt installs softgrain to bin/ and the script to
//     share/softgrain/), wherever the install prefix is;
//  2. the source tree's scripts/plot_run.py, its path fixed when the build was configured:
//     a fallback for running from a build tree, not for an installed tool.
// The interpreter is Debian's /usr/bin/python3 (python3-matplotlib, python3-numpy; the
// python3 first on PATH may be another installation without them).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sg {

inline constexpr const char* kPlotPython = "/usr/bin/python3";

// The running executable (/proc/self/exe); empty if it cannot be read.
std::filesystem::path current_executable();

// The script, or nullopt; every path tried is appended to `tried`.
std::optional<std::filesystem::path> find_plot_script(const std::filesystem::path& executable,
                                                      std::vector<std::filesystem::path>* tried);

// True if `python` exists and imports matplotlib and numpy (output silenced).
bool python_has_matplotlib(const std::filesystem::path& python = kPlotPython);

// Runs `python script run_dir arguments...`, its output going to ours; returns its exit
// status (127 if it could not be started, 128 + signal if killed).
int run_plot_script(const std::filesystem::path& script, const std::filesystem::path& run_dir,
                    const std::vector<std::string>& arguments = {},
                    const std::filesystem::path& python = kPlotPython);

}  // namespace sg
