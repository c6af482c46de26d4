#include "meshfree/mls.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace sg {

double cubic_spline_weight(double r) {
  if (r <= 0.5) return 2.0 / 3.0 - 4.0 * r * r + 4.0 * r * r * r;
  if (r < 1.0) return 4.0 / 3.0 - 4.0 * r + 4.0 * r * r - 4.0 / 3.0 * r * r * r;
  return 0.0;
}

double cubic_spline_weight_derivative(double r) {
  if (r <= 0.5) return -8.0 * r + 12.0 * r * r;
  if (r < 1.0) return -4.0 + 8.0 * r - 4.0 * r * r;
  return 0.0;
}

namespace {
double typical_spacing(std::span<const Vec2> nodes) {
  Vec2 lo = nodes.front(), hi = nodes.front();
  for (const Vec2& p : nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec2 extent = (hi - lo).cwiseMax(1e-300);
  return std::max(std::sqrt(extent.x() * extent.y() / static_cast<double>(nodes.size())),
                  1e-12 * extent.maxCoeff());
}
}  // namespace

MlsShapeFunctions::MlsShapeFunctions(std::span<const Vec2> nodes, const MlsParams& params,
                                     std::string body_name, std::span<const double> min_support)
    : nodes_(nodes.begin(), nodes.end()),
      params_(params),
      body_name_(std::move(body_name)),
      grid_(nodes, nodes.empty() ? 1.0 : typical_spacing(nodes)) {
  SG_VERIFY(params.neighbours >= 3, "body '" << body_name_
                                             << "': MLS needs at least 3 neighbours, got "
                                             << params.neighbours);
  SG_VERIFY(params.support_factor >= 1.0, "body '" << body_name_
                                                   << "': MLS support factor must be >= 1, got "
                                                   << params.support_factor);
  SG_VERIFY(nodes_.size() > static_cast<std::size_t>(params.neighbours),
            "body '" << body_name_ << "' has " << nodes_.size() << " nodes, fewer than the "
                     << params.neighbours + 1 << " an MLS support needs (neighbours + 1)");
  SG_ASSERT(min_support.empty() || min_support.size() == nodes_.size(),
            "min_support has " << min_support.size() << " radii for " << nodes_.size() << " nodes");
  support_radius_.resize(nodes_.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    support_radius_[i] = params.support_factor *
                         grid_.kth_neighbour_distance(static_cast<int>(i), params.neighbours);
    if (!min_support.empty()) support_radius_[i] = std::max(support_radius_[i], min_support[i]);
    max_support_ = std::max(max_support_, support_radius_[i]);
    sum += support_radius_[i];
  }
  basis_scale_ = sum / static_cast<double>(nodes_.size());
}

void MlsShapeFunctions::evaluate(const Vec2& point, ShapeRows& rows) const {
  using Vec3 = Eigen::Vector3d;
  using Mat3 = Eigen::Matrix3d;
  // Gather the covering nodes with their weights and weight gradients.
  struct Covering {
    int node;
    Vec3 p;    // shifted, scaled basis at the node
    double w;  // weight
    Vec2 dw;   // d w / d x
  };
  std::vector<Covering> cover;
  cover.reserve(32);
  grid_.for_each_within(point, max_support_, [&](int j) {
    const Vec2 d = point - nodes_[static_cast<std::size_t>(j)];
    const double rho = support_radius_[static_cast<std::size_t>(j)];
    const double dist = d.norm();
    if (dist >= rho) return;
    const double r = dist / rho;
    const double w = cubic_spline_weight(r);
    const Vec2 dw =
        dist > 0.0 ? Vec2(cubic_spline_weight_derivative(r) / (rho * dist) * d) : Vec2(0.0, 0.0);
    const Vec2 shifted = (nodes_[static_cast<std::size_t>(j)] - point) / basis_scale_;
    cover.push_back({j, Vec3(1.0, shifted.x(), shifted.y()), w, dw});
  });
  SG_VERIFY(cover.size() >= 3, "body '" << body_name_ << "': MLS point (" << point.x() << ", "
                                        << point.y() << ") is covered by " << cover.size()
                                        << " node supports, at least 3 are needed");

  Mat3 a = Mat3::Zero(), a_x = Mat3::Zero(), a_y = Mat3::Zero();
  for (const Covering& c : cover) {
    const Mat3 ppt = c.p * c.p.transpose();
    a += c.w * ppt;
    a_x += c.dw.x() * ppt;
    a_y += c.dw.y() * ppt;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(a, Eigen::EigenvaluesOnly);
  const double rcond = eig.eigenvalues().minCoeff() / eig.eigenvalues().maxCoeff();
  SG_VERIFY(rcond > params_.min_reciprocal_condition,
            "body '" << body_name_ << "': ill-conditioned MLS moment matrix at (" << point.x()
                     << ", " << point.y() << "): reciprocal condition " << rcond << " with "
                     << cover.size()
                     << " covering nodes (nodes nearly collinear; increase mls neighbours)");

  // gamma = A^-1 p(x); with the basis shifted to x, p(x) = [1, 0, 0] and its derivatives
  // are [0, 1/s, 0], [0, 0, 1/s] (Belytschko 1994 eqs. 11-12 written for gamma).
  const Eigen::LDLT<Mat3> solver(a);
  const Vec3 gamma = solver.solve(Vec3(1.0, 0.0, 0.0));
  const Vec3 gamma_x = solver.solve(Vec3(0.0, 1.0 / basis_scale_, 0.0) - a_x * gamma);
  const Vec3 gamma_y = solver.solve(Vec3(0.0, 0.0, 1.0 / basis_scale_) - a_y * gamma);

  for (const Covering& c : cover) {
    const double gp = gamma.dot(c.p);
    rows.node.push_back(c.node);
    rows.value.push_back(gp * c.w);
    rows.dndx.push_back(gamma_x.dot(c.p) * c.w + gp * c.dw.x());
    rows.dndy.push_back(gamma_y.dot(c.p) * c.w + gp * c.dw.y());
  }
  rows.offset.push_back(static_cast<std::int32_t>(rows.node.size()));
}

}  // namespace sg
