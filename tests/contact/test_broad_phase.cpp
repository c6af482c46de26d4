// Broad phase (broad_phase.h): no missed pair against brute force, periodic seam, Verlet
// rebuild trigger, determinism, bad input.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "contact/broad_phase.h"
#include "core/error.h"
#include "core/parallel.h"
#include "geometry/polygon.h"
#include "geometry/shapes.h"

namespace sg {
namespace {

// Brute-force reference: the distance from `node` to segment [a, b], minimum over the
// periodic images k = -1..1 (grains stay within one period of the cell; no use of the library's
// nearest-image rule).
double brute_distance(const BroadPhaseParams& params, const Vec2& node, const Vec2& a,
                      const Vec2& b) {
  double best = project_on_segment(node, a, b).distance;
  if (!params.periodic_x) return best;
  const double period = params.x_max - params.x_min;
  for (int k = -1; k <= 1; ++k) {
    best = std::min(best, project_on_segment(node + Vec2(k * period, 0.0), a, b).distance);
  }
  return best;
}

// A cloud of small polygonal grains moving rigidly (translation + spin) through each other;
// each grain's nodes are its vertices and its segments its edges. Grains are wrapped into
// the periodic cell as a whole when their centre leaves it (their nodes then extend past
// the seam, as a model that keeps bodies contiguous would have them).
struct MovingScene {
  BroadPhaseParams params;
  std::vector<Polygon> reference;  // shapes about their centre
  std::vector<Vec2> centre, velocity;
  std::vector<double> angle, spin;
  std::vector<Vec2> nodes, starts, ends;
  std::vector<int> node_body, segment_body;

  // `drift`: a velocity added to every grain's (the rebuild rule ignores a common
  // translation: broad_phase.h).
  MovingScene(const BroadPhaseParams& p, int grains, std::uint32_t seed,
              const Vec2& drift = Vec2(0.0, 0.0))
      : params(p) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int g = 0; g < grains; ++g) {
      const double radius = 0.2 + 0.3 * unit(rng);
      reference.push_back(make_ellipse(Vec2(0, 0), radius, 0.6 * radius, 0.0, radius * 0.5));
      centre.emplace_back(p.x_min + (p.x_max - p.x_min) * unit(rng), 3.0 * unit(rng));
      velocity.push_back(drift + Vec2(2.0 * unit(rng) - 1.0, 0.4 * unit(rng) - 0.2));
      angle.push_back(6.0 * unit(rng));
      spin.push_back(2.0 * unit(rng) - 1.0);
    }
    update();
  }

  void advance(double dt) {
    const double period = params.x_max - params.x_min;
    for (std::size_t g = 0; g < centre.size(); ++g) {
      centre[g] += dt * velocity[g];
      angle[g] += dt * spin[g];
      if (params.periodic_x && centre[g].x() >= params.x_max) centre[g].x() -= period;
      if (params.periodic_x && centre[g].x() < params.x_min) centre[g].x() += period;
    }
    update();
  }

  void update() {
    nodes.clear(), starts.clear(), ends.clear(), node_body.clear(), segment_body.clear();
    for (std::size_t g = 0; g < centre.size(); ++g) {
      const Mat2 r = rotation(angle[g]);
      const std::size_t first = nodes.size();
      for (const Vec2& v : reference[g]) {
        nodes.push_back(centre[g] + r * v);
        node_body.push_back(static_cast<int>(g));
      }
      for (std::size_t i = first; i < nodes.size(); ++i) {
        starts.push_back(nodes[i]);
        ends.push_back(i + 1 < nodes.size() ? nodes[i + 1] : nodes[first]);
        segment_body.push_back(static_cast<int>(g));
      }
    }
  }

  BroadPhaseInput input() const { return {nodes, node_body, starts, ends, segment_body}; }
};

bool listed(std::span<const ContactCandidate> list, int node, int segment) {
  return std::binary_search(list.begin(), list.end(), ContactCandidate{node, segment, 0.0},
                            [](const ContactCandidate& a, const ContactCandidate& b) {
                              return a.node != b.node ? a.node < b.node : a.segment < b.segment;
                            });
}

bool sorted(std::span<const ContactCandidate> list) {
  return std::is_sorted(list.begin(), list.end(), [](const auto& a, const auto& b) {
    return a.node != b.node ? a.node < b.node : a.segment < b.segment;
  });
}

// At every step: if the broad phase says so, rebuild; then every pair closer than the
// cutoff (brute force over all pairs of different bodies and all images) must be listed.
// The grains cross the seam many times; the test also counts what it exercised, so that a
// scene without contacts or rebuilds cannot pass silently.
// The moving scenes' steps: max speed ~1.1 (+ spin x radius ~0.5), ~0.006 per step.
constexpr int kSceneSteps = 300;
constexpr double kSceneDt = 0.004;

// The periodic cell of the moving scenes.
BroadPhaseParams periodic_scene_params() {
  BroadPhaseParams params;
  params.cutoff = 0.05;
  params.skin = 0.06;
  params.periodic_x = true;
  params.x_min = -2.0;
  params.x_max = 3.0;
  return params;
}

// `builds`: where to leave the number of builds (ASSERT_* needs a void function).
void run_no_missed_contact(const BroadPhaseParams& params, std::uint32_t seed,
                           const Vec2& drift = Vec2(0.0, 0.0), int* builds = nullptr) {
  MovingScene scene(params, 36, seed, drift);
  BroadPhase broad(params);
  int checked_pairs = 0, seam_pairs = 0;
  for (int step = 0; step < kSceneSteps; ++step) {
    if (broad.needs_rebuild(scene.input())) broad.build(scene.input());
    const auto list = broad.candidates();
    ASSERT_TRUE(sorted(list));
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
      for (std::size_t s = 0; s < scene.starts.size(); ++s) {
        if (scene.node_body[n] == scene.segment_body[s]) continue;
        const double d = brute_distance(params, scene.nodes[n], scene.starts[s], scene.ends[s]);
        if (d >= params.cutoff) continue;
        ++checked_pairs;
        const double direct =
            project_on_segment(scene.nodes[n], scene.starts[s], scene.ends[s]).distance;
        if (direct > d) ++seam_pairs;  // found only through a periodic image
        ASSERT_TRUE(listed(list, static_cast<int>(n), static_cast<int>(s)))
            << "step " << step << ": node " << n << " segment " << s << " at distance " << d
            << " is missing (builds: " << broad.build_count() << ")";
        // The nearest-image shift, recomputed now, brings the node within the cutoff.
        const double shift =
            nearest_image_shift(params, scene.nodes[n], scene.starts[s], scene.ends[s]);
        EXPECT_NEAR(
            project_on_segment(scene.nodes[n] + Vec2(shift, 0.0), scene.starts[s], scene.ends[s])
                .distance,
            d, 1e-12);
      }
    }
    scene.advance(kSceneDt);
  }
  EXPECT_GT(checked_pairs, 1000);
  EXPECT_GT(broad.build_count(), 10);           // the skin was used up many times ...
  EXPECT_LT(broad.build_count(), kSceneSteps);  // ... but not at every step
  if (params.periodic_x) {
    EXPECT_GT(seam_pairs, 10);
  }
  if (builds != nullptr) *builds = broad.build_count();
}

TEST(BroadPhase, NoMissedPairVersusBruteForcePeriodic) {
  run_no_missed_contact(periodic_scene_params(), 7);
  run_no_missed_contact(periodic_scene_params(), 1234);
}

TEST(BroadPhase, NoMissedPairVersusBruteForceNotPeriodic) {
  BroadPhaseParams params;
  params.cutoff = 0.05;
  params.skin = 0.06;
  params.x_min = -2.0;  // only the initial placement uses the interval here
  params.x_max = 3.0;
  run_no_missed_contact(params, 99);
}

// The grains of the periodic case with a common drift of (3, -1) added to their velocities
// (three times their own speeds): nothing is missed, and the rebuilds are as frequent as
// without the drift (counted without the brute-force check), since only the displacements
// less the centre of their box count. (A rule on the displacements themselves would rebuild
// at least each time the drift alone has carried everything by half the skin: every 2.4
// steps, 125 times in 300 steps.)
TEST(BroadPhase, ACommonTranslationNeitherMissesPairsNorCostsRebuilds) {
  const BroadPhaseParams params = periodic_scene_params();
  int drifting = 0;
  run_no_missed_contact(params, 7, Vec2(3.0, -1.0), &drifting);
  MovingScene scene(params, 36, 7);
  BroadPhase broad(params);
  for (int step = 0; step < kSceneSteps; ++step, scene.advance(kSceneDt))
    if (broad.needs_rebuild(scene.input())) broad.build(scene.input());
  const int still = broad.build_count();
  std::printf("builds in 300 steps: %d without the drift, %d with it\n", still, drifting);
  EXPECT_LE(drifting, still + still / 5);
}

TEST(BroadPhase, BuildListsExactlyThePairsWithinCutoffPlusSkin) {
  BroadPhaseParams params;
  params.cutoff = 0.05;
  params.skin = 0.1;
  params.periodic_x = true;
  params.x_max = 4.0;
  const MovingScene scene(params, 30, 5);
  BroadPhase broad(params);
  broad.build(scene.input());
  std::vector<ContactCandidate> expected;
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    for (std::size_t s = 0; s < scene.starts.size(); ++s) {
      if (scene.node_body[n] == scene.segment_body[s]) continue;
      const double d = brute_distance(params, scene.nodes[n], scene.starts[s], scene.ends[s]);
      if (d < params.cutoff + params.skin) {
        expected.push_back(
            {static_cast<int>(n), static_cast<int>(s),
             nearest_image_shift(params, scene.nodes[n], scene.starts[s], scene.ends[s])});
      }
    }
  }
  ASSERT_GT(expected.size(), 100u);
  const std::vector<ContactCandidate> got(broad.candidates().begin(), broad.candidates().end());
  EXPECT_EQ(got, expected);  // same pairs, same shifts, same (sorted) order
  // Determinism: a second build from the same input gives the same bits.
  broad.build(scene.input());
  EXPECT_EQ(std::vector<ContactCandidate>(broad.candidates().begin(), broad.candidates().end()),
            got);
}

TEST(BroadPhase, ManySegmentsAreBinnedInParallelWithTheSameList) {
  // Over kParallelContourPoints segments the binning runs in parallel (broad_phase.cpp), and
  // the order of a cell's segments then depends on the threads: the list must not. 1,200
  // grains in a cell 100 long; the list is checked against brute force for every 40th node.
  BroadPhaseParams params = periodic_scene_params();
  params.x_max = 98.0;
  const MovingScene scene(params, 1200, 11);
  ASSERT_GE(scene.starts.size(), kParallelContourPoints);
  const auto build_on = [&](int threads) {
    omp_set_num_threads(threads);
    BroadPhase broad(params);
    broad.build(scene.input());
    return std::vector<ContactCandidate>(broad.candidates().begin(), broad.candidates().end());
  };
  const std::vector<ContactCandidate> one = build_on(1), two = build_on(2);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_EQ(one, two);
  ASSERT_TRUE(sorted(two));
  int checked = 0;
  for (std::size_t n = 0; n < scene.nodes.size(); n += 40)
    for (std::size_t s = 0; s < scene.starts.size(); ++s) {
      if (scene.node_body[n] == scene.segment_body[s]) continue;
      const double d = brute_distance(params, scene.nodes[n], scene.starts[s], scene.ends[s]);
      const bool within = d < params.cutoff + params.skin;
      checked += within;
      EXPECT_EQ(listed(two, static_cast<int>(n), static_cast<int>(s)), within)
          << "node " << n << " segment " << s << " at distance " << d;
    }
  EXPECT_GT(checked, 100);
}

TEST(BroadPhase, FindsPairAcrossTheSeamWithItsShift) {
  BroadPhaseParams params;
  params.cutoff = 0.05;
  params.skin = 0.02;
  params.periodic_x = true;
  params.x_min = 0.0;
  params.x_max = 10.0;
  const std::vector<Vec2> nodes = {Vec2(0.01, 0.03), Vec2(5.0, 0.03)};
  const std::vector<int> node_body = {0, 0};
  const std::vector<Vec2> starts = {Vec2(9.99, 0.0)}, ends = {Vec2(9.95, 0.0)};
  const std::vector<int> segment_body = {1};
  BroadPhase broad(params);
  broad.build({nodes, node_body, starts, ends, segment_body});
  ASSERT_EQ(broad.candidates().size(), 1u);
  EXPECT_EQ(broad.candidates()[0].node, 0);
  EXPECT_EQ(broad.candidates()[0].shift_x, 10.0);  // node image at x = 10.01

  // Without periodicity the same pair is 9.96 apart: not listed.
  params.periodic_x = false;
  BroadPhase flat(params);
  flat.build({nodes, node_body, starts, ends, segment_body});
  EXPECT_TRUE(flat.candidates().empty());
}

// The displacements less the centre of their box (broad_phase.h): a rebuild when the box's
// diagonal exceeds the skin, so one point alone may move by the skin, two in opposite
// directions by half of it each, and everything together by any amount.
TEST(BroadPhase, RebuildTriggerIsTheSkinOfRelativeMotion) {
  BroadPhaseParams params;
  params.cutoff = 0.05;
  params.skin = 0.2;
  params.periodic_x = true;
  params.x_min = 0.0;
  params.x_max = 10.0;
  std::vector<Vec2> nodes = {Vec2(1, 1), Vec2(9.95, 2)};
  const std::vector<int> node_body = {0, 1};
  std::vector<Vec2> starts = {Vec2(3, 3)}, ends = {Vec2(3.5, 3)};
  const std::vector<int> segment_body = {2};
  const auto input = [&] { return BroadPhaseInput{nodes, node_body, starts, ends, segment_body}; };
  BroadPhase broad(params);
  EXPECT_TRUE(broad.needs_rebuild(input()));  // never built
  broad.build(input());
  EXPECT_FALSE(broad.needs_rebuild(input()));

  nodes[0] = Vec2(1.0 + 0.199, 1.0);  // alone: 0.995 skin from everything else
  EXPECT_FALSE(broad.needs_rebuild(input()));
  nodes[0] = Vec2(1.0 + 0.201, 1.0);  // 1.005 skin
  EXPECT_TRUE(broad.needs_rebuild(input()));
  nodes[0] = Vec2(1.0, 1.0 - 0.201);  // any direction
  EXPECT_TRUE(broad.needs_rebuild(input()));
  nodes[0] = Vec2(1.0 + 0.12, 1.0 + 0.12);  // 0.17 along the diagonal, the box's diagonal too
  EXPECT_FALSE(broad.needs_rebuild(input()));
  nodes[0] = Vec2(1.0 + 0.099, 1.0);  // towards each other by about half the skin ...
  starts[0] = Vec2(3.0 - 0.099, 3.0);
  ends[0] = Vec2(3.5 - 0.099, 3.0);
  EXPECT_FALSE(broad.needs_rebuild(input()));
  starts[0] = Vec2(3.0 - 0.102, 3.0);  // ... and a little more
  EXPECT_TRUE(broad.needs_rebuild(input()));
  nodes[0] = Vec2(1, 1), starts[0] = Vec2(3, 3), ends[0] = Vec2(3.5, 3);

  // Everything moved together by more than the skin, across the seam for one node: no rebuild.
  const Vec2 shift(0.7, -0.4);
  nodes[0] += shift, nodes[1] = Vec2(9.95 + 0.7 - 10.0, 2.0 - 0.4), starts[0] += shift,
                     ends[0] += shift;
  EXPECT_FALSE(broad.needs_rebuild(input()));
  nodes[0] += Vec2(0.21, 0.0);  // one of them further by more than the skin
  EXPECT_TRUE(broad.needs_rebuild(input()));
  nodes = {Vec2(1, 1), Vec2(9.95, 2)}, starts[0] = Vec2(3, 3), ends[0] = Vec2(3.5, 3);

  // Wrapped across the seam: moved by 0.1 - 0.05 = 0.05 only, not by the period.
  nodes[1] = Vec2(0.0, 2.0);
  EXPECT_FALSE(broad.needs_rebuild(input()));
  nodes[1] = Vec2(9.95, 2);

  // Segment end points count too.
  ends[0] = Vec2(3.5, 3.201);
  EXPECT_TRUE(broad.needs_rebuild(input()));
  ends[0] = Vec2(3.5, 3);

  // A change in the number of nodes forces a rebuild.
  nodes.push_back(Vec2(5, 5));
  const std::vector<int> three_bodies = {0, 1, 0};
  EXPECT_TRUE(broad.needs_rebuild({nodes, three_bodies, starts, ends, segment_body}));
}

std::string error_of(const auto& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(BroadPhase, BadParametersAreClearErrors) {
  BroadPhaseParams params;
  params.cutoff = 0.0;
  params.skin = 0.1;
  EXPECT_NE(error_of([&] { BroadPhase b(params); }).find("cutoff must be > 0"), std::string::npos);
  params.cutoff = 0.1;
  params.skin = -0.1;
  EXPECT_NE(error_of([&] { BroadPhase b(params); }).find("skin must be >= 0"), std::string::npos);
  params.skin = 0.1;
  params.periodic_x = true;
  params.x_min = 1.0;
  params.x_max = 1.0;
  EXPECT_NE(error_of([&] { BroadPhase b(params); }).find("is empty"), std::string::npos);

  // A period too short for one image per node: 0.5 < 2 (0.1 + 0.1) + 0.2.
  params.x_max = 1.5;
  const std::vector<Vec2> nodes = {Vec2(1.1, 0)}, starts = {Vec2(1.2, 0)}, ends = {Vec2(1.4, 0)};
  const std::vector<int> node_body = {0}, segment_body = {1};
  BroadPhase broad(params);
  EXPECT_NE(error_of([&] {
              broad.build({nodes, node_body, starts, ends, segment_body});
            }).find("must be longer than"),
            std::string::npos);
  // Mismatched array sizes.
  const std::vector<int> no_owner;
  EXPECT_NE(error_of([&] {
              broad.build({nodes, no_owner, starts, ends, segment_body});
            }).find("node owners"),
            std::string::npos);
}

// A NaN must not slip through the bounding box (Eigen's cwiseMin may pass over it): the error
// names the node or segment and its body.
TEST(BroadPhase, NonFinitePositionNamesTheNodeOrSegment) {
  BroadPhaseParams params;
  params.cutoff = 0.1;
  params.skin = 0.1;
  std::vector<Vec2> nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)};
  std::vector<Vec2> starts = {Vec2(0, 1), Vec2(1, 1)}, ends = {Vec2(1, 1), Vec2(2, 1)};
  const std::vector<int> node_body = {0, 0, 1}, segment_body = {2, 3};
  BroadPhase broad(params);
  const auto build_error = [&] {
    return error_of([&] { broad.build({nodes, node_body, starts, ends, segment_body}); });
  };
  EXPECT_EQ(build_error(), "");
  // Not first (the box starts from node 0): a NaN met later by cwiseMin.
  nodes[2] = Vec2(std::nan(""), 0.0);
  const std::string node_error = build_error();
  EXPECT_NE(node_error.find("node 2 (body 1) has a non-finite position"), std::string::npos)
      << node_error;
  nodes[2] = Vec2(2, 0);
  ends[1] = Vec2(2.0, std::numeric_limits<double>::infinity());
  const std::string segment_error = build_error();
  EXPECT_NE(segment_error.find("segment 1 (body 3) has a non-finite end point"), std::string::npos)
      << segment_error;
}

}  // namespace
}  // namespace sg
