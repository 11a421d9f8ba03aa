#include "indentation/elastic_face.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace si {

ElasticFace::ElasticFace(std::shared_ptr<const SupportKernel> kernel, const ShellPart& shell,
                         const ContactBody& body, const ContactRows& rows, double zone_bound)
    : shell_(shell), body_(body), rows_(rows), zone_bound_(zone_bound), zone_radius_(zone_bound) {
  const ShellModel& model = shell.model();
  for (const Support& s : model.supports)
    if (s.kind == SupportKind::kSymmetryPlane) {
      const std::vector<int>& set = model.mesh.node_sets.at(s.node_set);
      SI_REQUIRE(!set.empty(), "ElasticFace: an empty symmetry plane");
      mirrors_.push_back({s.plane_axis, model.mesh.nodes[set.front()][s.plane_axis]});
    }
  // The diagonal of the box of the reachable face points and their images bounds every distance
  // asked; the largest disc (four coincident images) too.
  Eigen::AlignedBox3d box;
  double r_max = 0;
  for (int a : body.reachable()) {
    r_max = std::max(r_max, std::sqrt(4 * shell.tributary_area(a) / kPi));
    for (const Vector3d& image : images(body.face_points()[a])) box.extend(image);
  }
  if (!box.isEmpty()) r_max = std::max(r_max, box.diagonal().norm());
  const double reach = 1.01 * r_max + 1e-9;
  SupportSpec mid = kernel->spec();
  mid.surface = PlateSurface::kMid;
  mid_plane_ =
      std::make_unique<FaceInfluence>(std::make_shared<const SupportKernel>(mid, 1.0), reach);
  influence_ = std::make_unique<FaceInfluence>(std::move(kernel), reach);
  if (zone_radius_ >= 0) {
    int zone = 0;
    for (int a : body.reachable()) zone += in_zone(a);
    if (zone > kMaxZoneNodes)
      throw_input("the elastic face's Newton block would couple " + std::to_string(zone) +
                      " contact nodes (within " + std::to_string(zone_radius_) +
                      " mm of the first touch, the sphere's chord at depth_max), more than " +
                      std::to_string(kMaxZoneNodes) +
                      ": use linear kinematics (the fast path has no block), a coarser apex "
                      "mesh or a smaller path.depth_max",
                  Where{"", "contact.local_support", "shell", 0});
    zone_radius_ = zone_bound_ / 4;
  }
}

std::vector<Vector3d> ElasticFace::images(const Vector3d& x) const {
  std::vector<Vector3d> out{x};
  for (const Mirror& m : mirrors_) {
    const std::size_t n = out.size();
    for (std::size_t i = 0; i < n; ++i) {
      Vector3d y = out[i];
      y[m.axis] = 2 * m.at - y[m.axis];
      out.push_back(y);
    }
  }
  return out;
}

bool ElasticFace::in_zone(int node) const {
  if (zone_radius_ <= 0) return true;
  const std::vector<Vector3d>& x = body_.face_points();
  return (x[node] - x[body_.first_node()]).norm() <= zone_radius_;
}

std::vector<int> ElasticFace::coupling_members(const std::vector<int>& nodes) const {
  if (zone_radius_ < 0) return {};
  keep_columns_of(nodes);
  return zone_members_;
}

bool ElasticFace::adapt(const std::vector<int>& nodes,
                        const Eigen::Ref<const cont::Vector>& lambda) {
  if (zone_radius_ <= 0 || zone_radius_ >= zone_bound_) return false;
  const std::vector<Vector3d>& x = body_.face_points();
  double reach = 0;  // of the pressed nodes from the first touch
  for (int i = 0; i < static_cast<int>(nodes.size()); ++i)
    if (lambda[i] > 0) reach = std::max(reach, (x[nodes[i]] - x[body_.first_node()]).norm());
  if (reach <= kZoneFill * zone_radius_) return false;
  set_zone(std::min(zone_bound_, kZoneGrowth * reach));
  return true;
}

void ElasticFace::set_zone(double radius) {
  zone_radius_ = radius;
  column_nodes_.clear();  // the columns and the members hold the old zone's couplings
  columns_.clear();
}

double ElasticFace::coefficient(const FaceInfluence& kernel, int a, int b) const {
  if (a != b && !(in_zone(a) && in_zone(b))) return 0.0;
  const std::vector<Vector3d>& x = body_.face_points();
  // Images closer than this to x_a are x_a itself: the node's own disc, which the coincident
  // images share (a node on a symmetry plane carries half its physical force and area).
  const double own = 1e-9 * (1 + x[a].norm());
  double c = 0;
  int coincident = 0;
  for (const Vector3d& image : images(x[b])) {
    const double r = (x[a] - image).norm();
    if (r <= own)
      ++coincident;
    else if (r <= kernel.r_max())  // beyond: a candidate added later, far from the contact
      c += kernel.point(r);
  }
  if (coincident > 0) {
    const double radius = std::sqrt(coincident * shell_.tributary_area(a) / kPi);
    c += coincident * kernel.disc(radius);
  }
  return c;
}

std::vector<double> ElasticFace::adapted() const {
  if (zone_bound_ <= 0) return {};
  return {zone_radius_};
}

bool ElasticFace::restore_adapted(const std::vector<double>& values) {
  if (zone_bound_ <= 0) return values.empty();
  // A radius adapt() can reach: from a quarter of the bound up to the bound.
  if (values.size() != 1 || !(values[0] >= zone_bound_ / 4 && values[0] <= zone_bound_))
    return false;
  set_zone(values[0]);
  return true;
}

double ElasticFace::own(int node) const {
  if (own_.empty())
    own_.assign(shell_.model().mesh.nodes.size(), std::numeric_limits<double>::quiet_NaN());
  double& c = own_[node];
  if (std::isnan(c)) c = coefficient(*influence_, node, node);
  return c;
}

// Candidates appended (ContactRows::adapt: the old set a prefix of the new) extend the kept
// columns by their own rows; any other change drops them.
void ElasticFace::keep_columns_of(const std::vector<int>& nodes) const {
  if (nodes == column_nodes_ && !nodes.empty()) return;
  const std::size_t kept = column_nodes_.size();
  const bool appended = kept > 0 && nodes.size() > kept &&
                        std::equal(column_nodes_.begin(), column_nodes_.end(), nodes.begin());
  if (!appended) {
    columns_.clear();
    zone_members_.clear();
  }
  const int from = appended ? static_cast<int>(kept) : 0;
  const int n = static_cast<int>(nodes.size());
  for (int j = 0; j < static_cast<int>(columns_.size()); ++j) {
    Eigen::VectorXd& c = columns_[j];
    if (c.size() == 0) continue;
    c.conservativeResize(n);
    for (int i = from; i < n; ++i) c[i] = coefficient(nodes[i], nodes[j]);
  }
  columns_.resize(nodes.size());
  for (int j = from; j < n; ++j)
    if (in_zone(nodes[j])) zone_members_.push_back(j);
  column_nodes_ = nodes;
}

const Eigen::VectorXd& ElasticFace::column(const std::vector<int>& nodes, int j) const {
  Eigen::VectorXd& c = columns_[j];
  if (c.size() == 0) {
    c.resize(static_cast<Eigen::Index>(nodes.size()));
    for (int i = 0; i < static_cast<int>(nodes.size()); ++i) c[i] = coefficient(nodes[i], nodes[j]);
  }
  return c;
}

void ElasticFace::prepare(const std::vector<int>& nodes,
                          const Eigen::Ref<const cont::Vector>& lambda) const {
  keep_columns_of(nodes);
  approach_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nodes.size()));
  for (int j = 0; j < static_cast<int>(nodes.size()); ++j)
    if (lambda[j] != 0) approach_ += lambda[j] * column(nodes, j);
  prepared_for_ = lambda.data();
}

double ElasticFace::layer(const std::vector<int>& nodes, int i,
                          const Eigen::Ref<const cont::Vector>& lambda) const {
  if (lambda.data() == prepared_for_ && approach_.size() == lambda.size()) return approach_[i];
  double u = 0;
  for (int j = 0; j < static_cast<int>(nodes.size()); ++j)
    if (lambda[j] != 0) u += coefficient(nodes[i], nodes[j]) * lambda[j];
  return u;
}

void ElasticFace::add_compliance_column(const std::vector<int>& nodes, int j,
                                        Eigen::VectorXd& column_j) const {
  keep_columns_of(nodes);
  column_j += column(nodes, j);
}

void ElasticFace::outputs(const TermPoint& p, IndentationState& out) const {
  const ShellModel& model = shell_.model();
  const std::vector<int>& nodes = rows_.candidates();
  const Eigen::Ref<const cont::Vector> lambda = rows_.multipliers(p.z);
  prepare(nodes, lambda);
  for (int i = 0; i < rows_.size(); ++i) {
    if (lambda[i] == 0 && nodes[i] != model.apex_node()) continue;
    const double approach = approach_[i];
    out.local_energy += model.symmetry_factor * 0.5 * lambda[i] * approach;
    if (nodes[i] == model.apex_node()) out.local_indentation = approach;
  }
  for (int j = 0; j < rows_.size(); ++j)
    if (lambda[j] != 0)
      out.apex_mid_deflection += coefficient(*mid_plane_, model.apex_node(), nodes[j]) * lambda[j];
}

}  // namespace si
