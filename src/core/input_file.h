#pragma once
// Files a user names as input (a scenario, the CSV files it points to, a campaign file):
// checked by type and length before they are opened. Opening a FIFO blocks until someone
// writes to it, a folder opens as an empty stream (its "missing keys" would then mislead), and
// /dev/zero never ends; a name of a megabyte makes every message a megabyte long
// (docs/scenario.md, "Safety").
#include <filesystem>
#include <string>

namespace sg {

// Longest path accepted, in bytes (Linux's PATH_MAX), and longest file name (NAME_MAX).
inline constexpr std::size_t kMaxPathBytes = 4096;
inline constexpr std::size_t kMaxFileNameBytes = 255;

// The magnitudes a number read from an input file may have: a positive quantity at least
// kMinInputMagnitude, any number at most kMaxInputMagnitude. Far beyond any unit system, and
// small enough that the products a run forms (energies: density x area x velocity^2) stay
// finite and non-zero: a density of 1e300 used to end in NaN energies, exit 0 (issue #26).
inline constexpr double kMaxInputMagnitude = 1e100;
inline constexpr double kMinInputMagnitude = 1e-100;

// `path` for a message: quoted, shortened to its first 200 bytes with "..." when longer.
std::string shown_path(const std::filesystem::path& path);

// Why `path` cannot be read as an input file, "" if it can: too long, missing, a folder, a
// FIFO, a device, a socket. E.g. "is a FIFO (named pipe), not a regular file".
std::string input_file_problem(const std::filesystem::path& path);

// Throws sg::Error "<what> <shown path> <problem>" if input_file_problem finds one.
void require_input_file(const std::filesystem::path& path, const std::string& what);

}  // namespace sg
