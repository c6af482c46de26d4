#pragma once
// Errors and the three tiers of checks (docs/architecture.md §Conventions 7 and 8).
//
//   SG_VERIFY(cond, msg)   always on: user input and user-facing invariants. Throws sg::Error.
//   SG_ASSERT(cond, msg)   programming errors; on unless NDEBUG (debug, relwithdebinfo builds).
//   SG_VALIDATE(cond, msg) heavy whole-state checks; on only with -DSOFTGRAIN_VALIDATE=ON (CI).
//
// `msg` is a stream expression: SG_VERIFY(nu < 0.5, "body '" << name << "': poisson " << nu).
// Errors are raised where the context (file, key, body, node, step) is known, and printed
// once by the top level.
//
// Why exceptions, where many simulation codes abort on a failed check: the engine is a library
// that the command line, the tests and the campaign runner call, and an error must reach the
// top level with its context and be printed once; the step controller also recovers from a
// failed step (an inverted Gauss point, a non-finite value) by catching the sg::Error it raises
// and rolling the state back (solver/step_controller.h). An exception escaping an OpenMP region
// would terminate the program, so kernels that can fail return a per-item result
// (model/internal_forces.h) or run in parallel_for (core/parallel.h), which rethrows the lowest
// failing item's error after the loop; what a parallel loop looks up is checked before it runs
// (MaterialPairTable::verify_covers).
#include <sstream>
#include <stdexcept>
#include <string>

namespace sg {

// An error the user can act on: bad input, a diverging run, an unreadable file.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

[[noreturn]] void throw_error(const std::string& message, const char* file, int line,
                              bool with_location);

}  // namespace sg

#define SG_THROW(msg)                                                     \
  do {                                                                    \
    std::ostringstream sg_throw_stream_;                                  \
    sg_throw_stream_ << msg;                                              \
    ::sg::throw_error(sg_throw_stream_.str(), __FILE__, __LINE__, false); \
  } while (0)

#define SG_VERIFY(cond, msg)    \
  do {                          \
    if (!(cond)) SG_THROW(msg); \
  } while (0)

#define SG_INTERNAL_CHECK(cond, msg)                                       \
  do {                                                                     \
    if (!(cond)) {                                                         \
      std::ostringstream sg_check_stream_;                                 \
      sg_check_stream_ << "internal check failed: " #cond ": " << msg;     \
      ::sg::throw_error(sg_check_stream_.str(), __FILE__, __LINE__, true); \
    }                                                                      \
  } while (0)

#ifndef NDEBUG
#define SG_ASSERT(cond, msg) SG_INTERNAL_CHECK(cond, msg)
#else
#define SG_ASSERT(cond, msg) ((void)0)
#endif

#ifdef SOFTGRAIN_VALIDATE
#define SG_VALIDATE(cond, msg) SG_INTERNAL_CHECK(cond, msg)
#else
#define SG_VALIDATE(cond, msg) ((void)0)
#endif
