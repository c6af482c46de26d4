// The run stage's part of a checkpoint (run/run_loop_state.h): encoded by the run stage,
// stored by the checkpoint (io/checkpoint.h) as opaque bytes at the end of its payload, and
// decoded back whole; damaged bytes are refused naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "io/checkpoint.h"
#include "run/run_loop_state.h"
#include "scenes/scenario_files.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// A loop state with every member away from its default.
RunLoopState every_member_set() {
  RunLoopState s;
  s.next_snapshot = 7;
  s.next_series_time = 0.25;
  s.next_field_time = 0.5;
  s.next_checkpoint_time = 0.75;
  s.series_rows = 12;
  s.series_bytes = 3456;
  s.top_force_sum_x = -1.5;
  s.top_force_sum_y = 2.5;
  s.top_force_rows = 5;
  s.field_entries = {{0.0, "fields/000000.vtu"}, {0.1, "fields/000001.vtu"}};
  s.contact_entries = {{0.1, "contacts/000001.vtu"}};
  s.controller.dt = 1e-4;
  s.controller.stable_dt = 2e-4;
  s.controller.energy_scale = 3.0;
  s.controller.since_estimate = 4;
  s.controller.since_reduction = 5;
  s.controller.statistics.accepted = 6;
  s.controller.statistics.rejected = 1;
  s.controller.statistics.estimates = 2;
  s.controller.statistics.dt_min = 5e-5;
  s.controller.statistics.dt_max = 2e-4;
  s.controller.statistics.last_rejection = "energy grew";
  s.strain_snapshot_time = 0.1;
  s.strain_snapshot_norm = {0.01, 0.02, 0.03};
  return s;
}

void expect_equal(const RunLoopState& a, const RunLoopState& b) {
  EXPECT_EQ(a.next_snapshot, b.next_snapshot);
  EXPECT_EQ(a.next_series_time, b.next_series_time);
  EXPECT_EQ(a.next_field_time, b.next_field_time);
  EXPECT_EQ(a.next_checkpoint_time, b.next_checkpoint_time);
  EXPECT_EQ(a.series_rows, b.series_rows);
  EXPECT_EQ(a.series_bytes, b.series_bytes);
  EXPECT_EQ(a.top_force_sum_x, b.top_force_sum_x);
  EXPECT_EQ(a.top_force_sum_y, b.top_force_sum_y);
  EXPECT_EQ(a.top_force_rows, b.top_force_rows);
  EXPECT_EQ(a.field_entries, b.field_entries);
  EXPECT_EQ(a.contact_entries, b.contact_entries);
  EXPECT_EQ(a.controller.dt, b.controller.dt);
  EXPECT_EQ(a.controller.stable_dt, b.controller.stable_dt);
  EXPECT_EQ(a.controller.energy_scale, b.controller.energy_scale);
  EXPECT_EQ(a.controller.since_estimate, b.controller.since_estimate);
  EXPECT_EQ(a.controller.since_reduction, b.controller.since_reduction);
  EXPECT_EQ(a.controller.statistics.accepted, b.controller.statistics.accepted);
  EXPECT_EQ(a.controller.statistics.rejected, b.controller.statistics.rejected);
  EXPECT_EQ(a.controller.statistics.estimates, b.controller.statistics.estimates);
  EXPECT_EQ(a.controller.statistics.dt_min, b.controller.statistics.dt_min);
  EXPECT_EQ(a.controller.statistics.dt_max, b.controller.statistics.dt_max);
  EXPECT_EQ(a.controller.statistics.last_rejection, b.controller.statistics.last_rejection);
  EXPECT_EQ(a.strain_snapshot_time, b.strain_snapshot_time);
  EXPECT_EQ(a.strain_snapshot_norm, b.strain_snapshot_norm);
}

TEST(RunLoopState, EveryMemberSurvivesACheckpointFile) {
  const RunLoopState state = every_member_set();
  Checkpoint checkpoint;
  encode_run_loop_state(state, checkpoint.run_state);
  ASSERT_FALSE(checkpoint.run_state.empty());
  const fs::path file = scenes::process_temp_dir("run_loop_state") / "loop.bin";
  write_checkpoint(file, checkpoint);
  const Checkpoint read = read_checkpoint(file, checkpoint.fingerprint);
  // The checkpoint stores the run stage's bytes as they are.
  EXPECT_EQ(read.run_state, checkpoint.run_state);
  expect_equal(decode_run_loop_state(read.run_state, "test"), state);
}

TEST(RunLoopState, EncodingReusesTheBufferAndStartsAfresh) {
  std::string bytes = "left over from an earlier checkpoint";
  encode_run_loop_state(RunLoopState{}, bytes);
  std::string fresh;
  encode_run_loop_state(RunLoopState{}, fresh);
  EXPECT_EQ(bytes, fresh);
}

std::string decode_error(const std::string& bytes) {
  try {
    (void)decode_run_loop_state(bytes, "checkpoint 'x.bin'");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(RunLoopState, DamagedBytesAreRefusedNamingTheSource) {
  std::string bytes;
  encode_run_loop_state(every_member_set(), bytes);
  EXPECT_EQ(decode_error(bytes), "");
  // Cut inside the first member, and inside the last vector (whose count then exceeds it).
  EXPECT_EQ(decode_error(bytes.substr(0, 2)),
            "checkpoint 'x.bin': malformed payload (the payload ends early)");
  EXPECT_EQ(decode_error(bytes.substr(0, bytes.size() - 3)),
            "checkpoint 'x.bin': malformed payload (a count of 3 exceeds the payload)");
  EXPECT_EQ(decode_error(bytes + "z"),
            "checkpoint 'x.bin': malformed payload (unread bytes at its end)");
}

}  // namespace
}  // namespace sg
