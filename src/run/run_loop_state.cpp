#include "run/run_loop_state.h"

#include "core/error.h"
#include "io/binary_archive.h"

namespace sg {

void encode_run_loop_state(const RunLoopState& state, std::string& bytes) {
  BinaryWriter writer;
  writer.bytes.swap(bytes);
  writer.bytes.clear();
  writer(state);
  bytes.swap(writer.bytes);
}

RunLoopState decode_run_loop_state(std::string_view bytes, const std::string& source) {
  RunLoopState state;
  BinaryReader reader(bytes);
  try {
    reader(state);
  } catch (const MalformedPayload& m) {
    SG_THROW(source << ": malformed payload (" << m.what << ")");
  }
  SG_VERIFY(reader.at_end(), source << ": malformed payload (unread bytes at its end)");
  return state;
}

}  // namespace sg
