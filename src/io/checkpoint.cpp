#include "io/checkpoint.h"

#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <type_traits>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/binary_archive.h"

namespace sg {

namespace {

static_assert(std::endian::native == std::endian::little ||
              std::endian::native == std::endian::big);

constexpr char kMagic[8] = {'S', 'G', 'C', 'K', 'P', 'T', '\0', '\x1a'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;
constexpr std::size_t kHeaderBytes = sizeof kMagic + 4 + 4 + 8;
constexpr std::size_t kTrailerBytes = 8;

// FNV-1a 64 (Fowler, Noll, Vo): a checksum that catches flipped bytes and truncation, not
// an authentication; one pass over the payload, no table.
std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

// The ledger is a flat struct of doubles that grows with the physics (a new dissipation
// channel, a new energy): it is saved whole, its size first, so that a new member is saved
// without being listed here and a checkpoint from a build with another ledger is refused.
static_assert(std::is_trivially_copyable_v<EnergyLedger> &&
              sizeof(EnergyLedger) % sizeof(double) == 0);

using LedgerValues = std::array<double, sizeof(EnergyLedger) / sizeof(double)>;

void save_ledger(BinaryWriter& w, const EnergyLedger& e) {
  w(static_cast<std::uint32_t>(sizeof e));
  for (const double v : std::bit_cast<LedgerValues>(e))
    w(v);
}

void load_ledger(BinaryReader& r, EnergyLedger& e) {
  std::uint32_t size = 0;
  r(size);
  if (size != sizeof e)
    throw MalformedPayload{"its energy ledger has " + std::to_string(size) +
                           " bytes, this build's " + std::to_string(sizeof e) +
                           ": written by another softgrain version"};
  LedgerValues values;
  for (double& v : values)
    r(v);
  e = std::bit_cast<EnergyLedger>(values);
}

}  // namespace

// What the payload holds, field by field. Each describe() serves both directions
// (io/binary_archive.h): a field is listed once. A field added to
// one of these structs must be added here and kCheckpointFormatVersion bumped; the size
// checks below catch a forgotten one at compile time where they can.
template <class A, class S>
void describe(A& a, S& f) requires std::is_same_v<std::remove_const_t<S>, CheckpointFingerprint> {
  a(f.nodes);
  a(f.bodies);
  a(f.rigid_bodies);
  a(f.contour_points);
  a(f.gauss_points);
  a(f.model_hash);
  a(f.settings_hash);
}

template <class A, class S>
void describe(A& a, S& h) requires std::is_same_v<std::remove_const_t<S>, ContactHistoryEntry> {
  static_assert(sizeof(ContactHistory) == 72, "ContactHistory changed: update the checkpoint");
  a(h.slave_point);
  a(h.master_body);
  a(h.history.stored_slip);
  a(h.history.normal_gap);
  a(h.history.normal_traction);
  a(h.history.tangential_traction);
  a(h.history.energy);
  a(h.history.viscous_normal);
  a(h.history.viscous_tangential);
  a(h.history.damage);
  a(h.history.active);
  a(h.history.intact);
  a(h.history.unloading);
}

template <class A, class S>
void describe(A& a, S& r) requires std::is_same_v<std::remove_const_t<S>, ContactRecord> {
  a(r.slave_point);
  a(r.slave_body);
  a(r.master_body);
  a(r.master_segment);
  a(r.t);
  a(r.position);
  a(r.normal);
  a(r.gap);
  a(r.length);
  a(r.traction.normal);
  a(r.traction.tangential);
  a(r.traction.dissipated);
  a(r.traction.slipping);
  a(r.traction.bond_broken);
  a(r.active);
}

template <class A, class S>
void describe(A& a, S& c) requires std::is_same_v<std::remove_const_t<S>, ContactCandidate> {
  a(c.node);
  a(c.segment);
  a(c.shift_x);
}

template <class A, class S>
void describe(A& a, S& s) requires std::is_same_v<std::remove_const_t<S>, StateSnapshot> {
  // The arrays in the snapshot's schema (solver/state_snapshot.h), then the rest.
  for (const StateArray<NodeState>& row : kNodeStateArrays)
    a(s.*row.snapshot);
  for (const StateArray<RigidState>& row : kRigidStateArrays)
    a(s.*row.snapshot);
  a(s.drive_reaction);
  static_assert(sizeof(SolverState) == 2 * sizeof(double) + sizeof(long) + sizeof(EnergyLedger),
                "SolverState changed: update the checkpoint");
  a(s.solver.time);
  a(s.solver.step);
  a(s.solver.previous_dt);
  if constexpr (std::is_const_v<S>)
    save_ledger(a, s.solver.energy);
  else
    load_ledger(a, s.solver.energy);
  static_assert(sizeof(SolverPendingIncrements) == 5 * sizeof(double));
  a(s.pending.external_work);
  a(s.pending.damping_dissipation);
  a(s.pending.load_work);
  a(s.pending.servo_dissipation);
  a(s.pending.drive_work);
  a(s.has_contacts);
  a(s.contacts.histories);
  a(s.contacts.previous_positions);
  a(s.contacts.records);
  a(s.contacts.broad_phase.build_count);
  a(s.contacts.broad_phase.built_nodes);
  a(s.contacts.broad_phase.built_segment_start);
  a(s.contacts.broad_phase.built_segment_end);
  a(s.contacts.broad_phase.candidates);
}

CheckpointFingerprint fingerprint_of(const Model& model, std::span<const double> run_settings) {
  CheckpointFingerprint f;
  f.nodes = model.node_count();
  f.bodies = model.bodies.size();
  f.rigid_bodies = model.rigid.size();
  f.contour_points = model.contour_point_count();
  f.gauss_points = model.gauss_point_count();
  BinaryWriter w;
  for (const Body& b : model.bodies) {
    w(b.name);
    w(b.kind);
    w(b.material);
    w(b.node_begin);
    w(b.node_end);
    w(b.boundary_end);
    w(b.gauss_begin);
    w(b.gauss_end);
    w(b.contour_begin);
    w(b.contour_end);
    w(b.open_contour);
    w(b.closing_shift_x);
    w(b.reference_area);
  }
  for (const MaterialDef& m : model.material_defs) {
    w(m.name);
    w(m.law);
    w(m.young);
    w(m.poisson);
    w(m.density);
    w(m.damping);
    // Non-default damping models only, so that the fingerprints of earlier runs are unchanged.
    if (m.damping_model != DampingModel::objective) w(m.damping_model);
    if (m.volumetric != VolumetricFormulation::standard) w(m.volumetric);
  }
  w(model.nodes.ref_y);
  w(model.nodes.mass);
  w(model.gauss_weight);
  w(model.node_rows.value);
  w(model.rigid.mass);
  w(model.rigid.inertia);
  w(model.rigid_contour_offset);
  for (const RigidDrive& d : model.rigid.drive)
    for (int k = 0; k < 3; ++k) {
      w(d.mode[k]);
      w(d.velocity[k].times);
      w(d.velocity[k].values);
      w(d.force[k]);
      w(d.load[k].times);
      w(d.load[k].values);
      w(d.load_damping[k]);
    }
  for (const NodeDrive& d : model.node_drives) {
    w(d.body);
    w(d.nodes);
    for (int k = 0; k < 2; ++k) {
      w(d.mode[k]);
      w(d.velocity[k].times);
      w(d.velocity[k].values);
      w(d.load[k].times);
      w(d.load[k].values);
      w(d.load_damping[k]);
    }
  }
  w(model.gravity);
  w(model.periodic_x);
  w(model.x_min);
  w(model.x_max);
  f.model_hash = fnv1a(w.bytes);
  f.settings_hash = fnv1a(std::string_view(reinterpret_cast<const char*>(run_settings.data()),
                                           run_settings.size_bytes()));
  return f;
}

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint) {
  BinaryWriter payload;
  payload(checkpoint.fingerprint);
  payload(checkpoint.state);
  payload.bytes +=
      checkpoint.run_state;  // the run stage's, as it is (no count: it ends the payload)
  BinaryWriter file;
  file.bytes.append(kMagic, sizeof kMagic);
  file(kCheckpointFormatVersion);
  file(kByteOrderMark);
  file(static_cast<std::uint64_t>(payload.bytes.size()));
  file.bytes += payload.bytes;
  file(fnv1a(payload.bytes));
  write_file_atomically(path, file.bytes);
}

Checkpoint read_checkpoint(const std::filesystem::path& path,
                           const CheckpointFingerprint& expected) {
  const std::string name = "checkpoint '" + path.string() + "': ";
  std::ifstream in(path, std::ios::binary);
  SG_VERIFY(in, name << "cannot open the file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  SG_VERIFY(bytes.size() >= sizeof kMagic && std::memcmp(bytes.data(), kMagic, sizeof kMagic) == 0,
            name << "not a softgrain checkpoint (wrong magic number)");
  SG_VERIFY(bytes.size() >= kHeaderBytes, name << "truncated (" << bytes.size()
                                               << " bytes, the header alone is " << kHeaderBytes
                                               << ")");
  std::uint32_t version = 0, mark = 0;
  std::uint64_t payload_size = 0;
  std::memcpy(&version, bytes.data() + 8, 4);
  std::memcpy(&mark, bytes.data() + 12, 4);
  std::memcpy(&payload_size, bytes.data() + 16, 8);
  SG_VERIFY(mark == kByteOrderMark,
            name << "written on a machine of the other byte order (or damaged header)");
  SG_VERIFY(version == kCheckpointFormatVersion,
            name << "format version " << version << ", this softgrain reads version "
                 << kCheckpointFormatVersion << " (resume with the softgrain that wrote it)");
  const std::uint64_t expected_size = kHeaderBytes + payload_size + kTrailerBytes;
  SG_VERIFY(payload_size <= bytes.size() && bytes.size() >= expected_size,
            name << "truncated (" << bytes.size() << " bytes, the header announces "
                 << expected_size << ")");
  SG_VERIFY(bytes.size() == expected_size,
            name << bytes.size() - expected_size << " unexpected bytes after the checksum");
  const std::string_view payload(bytes.data() + kHeaderBytes, payload_size);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + kHeaderBytes + payload_size, 8);
  SG_VERIFY(checksum == fnv1a(payload), name << "corrupted (the checksum of the " << payload_size
                                             << "-byte payload does not match)");

  Checkpoint c;
  BinaryReader reader(payload);
  try {
    reader(c.fingerprint);
    const CheckpointFingerprint& f = c.fingerprint;
    SG_VERIFY(f.nodes == expected.nodes && f.bodies == expected.bodies &&
                  f.rigid_bodies == expected.rigid_bodies &&
                  f.contour_points == expected.contour_points &&
                  f.gauss_points == expected.gauss_points,
              name << "written for another model (" << f.bodies << " bodies, " << f.rigid_bodies
                   << " rigid, " << f.nodes << " nodes, " << f.contour_points << " contour points, "
                   << f.gauss_points << " Gauss points; this scenario has " << expected.bodies
                   << ", " << expected.rigid_bodies << ", " << expected.nodes << ", "
                   << expected.contour_points << ", " << expected.gauss_points << ")");
    SG_VERIFY(f.model_hash == expected.model_hash,
              name << "written for another model (same sizes, but other geometry, materials, "
                      "drives or periodic cell, or the bodies in another order: executables "
                      "before commit 76ed259 (softgrain --version) numbered generated grains in "
                      "drawn order, not along x)");
    SG_VERIFY(f.settings_hash == expected.settings_hash,
              name << "written with other run settings (time step, output periods or contact "
                      "laws)");
    reader(c.state);
    c.run_state = reader.take_rest();
  } catch (const MalformedPayload& m) {
    SG_THROW(name << "malformed payload (" << m.what << ")");
  }
  return c;
}

}  // namespace sg
