#pragma once
// What built this softgrain: the project version and the git commit of the source tree
// (`softgrain --version`; also written into run.log, summary.json, campaign.csv and the PNG
// pictures, so that a result names what produced it).
//
// The commit is compiled into one generated file (version.cpp.in -> <build>/src/core/
// version.cpp, rewritten by write_version.cmake at every build only when the commit or the
// tree's state changes), not into a header or a -D flag: a new commit then recompiles that
// one file and relinks, instead of recompiling everything that includes the header.
#include <string>
#include <string_view>

namespace sg {

// "0.1.0" (the project() version of the top-level CMakeLists.txt).
std::string_view softgrain_version();

// The commit's hash (12 hex digits), with "-dirty" when tracked files differed from it at
// build time; "unknown" when built outside a git checkout or without git.
std::string_view softgrain_commit();

// "softgrain 0.1.0 (commit 0123456789ab-dirty)": one line for logs and metadata.
std::string softgrain_version_line();

}  // namespace sg
