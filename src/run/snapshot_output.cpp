#include "run/snapshot_output.h"

#include <cstdio>

#include "io/contact_rate.h"
#include "io/contact_vtk.h"
#include "io/grain_snapshot_writer.h"

namespace sg {

SnapshotOutput::SnapshotOutput(RunContext& context)
    : context_(context),
      strain_rate_unit_(global_strain_rate(context.scenario)),
      fields_pvd_(context.folder.dir / "fields.pvd"),
      contacts_pvd_(context.folder.dir / "contacts.pvd") {}

namespace {

using PvdEntries = std::vector<std::pair<double, std::string>>;

// The entries of `entries` whose file is in `dir`; the others are named in `note`.
PvdEntries present_entries(const std::filesystem::path& dir, const PvdEntries& entries,
                           const char* index, std::string& note) {
  PvdEntries kept;
  std::string missing;
  std::size_t dropped = 0;
  for (const auto& entry : entries) {
    std::error_code error;
    if (std::filesystem::is_regular_file(dir / entry.second, error)) {
      kept.push_back(entry);
    } else if (++dropped <= 3) {
      missing += (missing.empty() ? "" : ", ") + entry.second;
    }
  }
  if (dropped > 0)
    note += "# resume: " + std::to_string(dropped) + " of the " + std::to_string(entries.size()) +
            " snapshots " + index + " listed are missing (" + missing +
            (dropped > 3 ? ", ..." : "") + "): " + index + " now lists only the files present\n";
  return kept;
}

}  // namespace

void SnapshotOutput::begin(bool resumed) {
  if (!resumed) return;
  const std::filesystem::path& dir = context_.folder.dir;
  RunLoopState& loop = context_.loop;
  loop.field_entries = present_entries(dir, loop.field_entries, "fields.pvd", resume_note_);
  fields_pvd_.restore(loop.field_entries);
  if (context_.simulation.contacts) {
    loop.contact_entries = present_entries(dir, loop.contact_entries, "contacts.pvd", resume_note_);
    contacts_pvd_.restore(loop.contact_entries);
  }
}

std::string SnapshotOutput::snapshot_name(const char* extension) const {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.%s", context_.loop.next_snapshot, extension);
  return std::string(name);
}

void SnapshotOutput::prepare(const RunInstant& now) {
  const auto& entries = fields_pvd_.entries();
  snapshot_due_ = now.time >= context_.loop.next_field_time - context_.time_tolerance &&
                  (entries.empty() || now.time > entries.back().first);
  if (snapshot_due_) write_state_files(now.time);
}

void SnapshotOutput::commit(const StepTaken& step) {
  if (!snapshot_due_) return;
  add_to_collections(step.start.time);
  context_.loop.next_field_time += context_.scenario.field_period;
}

void SnapshotOutput::finish() {
  write_state_files(context_.simulation.solver.state().time);
  Simulation& sim = context_.simulation;
  if (sim.contacts) {
    // The final state has had no force evaluation: its contact network is evaluated here,
    // on a copy of the state that is put back after (the evaluation moves the contact
    // histories and the rigid bodies' forces on; nothing else of the run changes).
    capture_state(sim.solver, sim.contacts.get(), final_state_);
    sim.contacts->add_contact_forces(
        sim.model, {sim.solver.state().previous_dt, sim.solver.state().step == 0});
    add_to_collections(sim.solver.state().time);
    restore_state(final_state_, sim.solver, sim.contacts.get());
  } else {
    add_to_collections(sim.solver.state().time);
  }
}

void SnapshotOutput::write_state_files(double time) {
  const std::filesystem::path& dir = context_.folder.dir;
  const Model& model = context_.simulation.model;
  const RunLoopState& loop = context_.loop;
  pending_time_ = time;
  pending_norm_ = nodal_strain_norms(model);
  const StrainInterval interval{loop.strain_snapshot_norm, time - loop.strain_snapshot_time};
  write_vtu_snapshot(model, dir / "fields" / snapshot_name("vtu"), strain_rate_unit_, interval,
                     context_.scenario.field_format);
  write_grain_snapshot(model, dir / "grains" / snapshot_name("csv"));
  if (context_.simulation.contacts) compute_contour_velocities(model, contour_velocity_);
}

void SnapshotOutput::add_to_collections(double time) {
  const std::string name = snapshot_name("vtu");
  RunLoopState& loop = context_.loop;
  fields_pvd_.add(time, "fields/" + name);
  loop.field_entries = fields_pvd_.entries();
  loop.strain_snapshot_time = pending_time_;
  loop.strain_snapshot_norm.swap(pending_norm_);
  if (const ContactSystem* contacts = context_.simulation.contacts.get()) {
    write_contact_snapshot(*contacts, context_.simulation.model, contour_velocity_,
                           strain_rate_unit_, context_.folder.dir / "contacts" / name,
                           context_.scenario.field_format);
    contacts_pvd_.add(time, "contacts/" + name);
    loop.contact_entries = contacts_pvd_.entries();
  }
  ++loop.next_snapshot;
}

}  // namespace sg
