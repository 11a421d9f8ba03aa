#include "model/assembler.hpp"

#include <omp.h>

#include <algorithm>
#include <exception>
#include <utility>

#include "core/error.hpp"

namespace si {

Assembler::Assembler(const Mesh& mesh, const DofMap& dofs, const ShellElement& element,
                     ShellLaw law, Kinematics kinematics, int threads)
    : mesh_(mesh),
      dofs_(dofs),
      element_(element),
      law_(std::move(law)),
      kinematics_(kinematics),
      threads_(threads) {
  SI_REQUIRE(dofs.num_nodes() == mesh.num_nodes(), "dof map and mesh differ in node count");
  SI_REQUIRE(static_cast<int>(mesh.directors.size()) == mesh.num_nodes(),
             "mesh needs one director per node");
  SI_REQUIRE(threads >= 0, "number of assembly threads must be >= 0");
  geometry_.resize(mesh.num_elements());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    for (int a = 0; a < 4; ++a) {
      const int n = mesh.elements[e][a];
      if (n < 0 || n >= mesh.num_nodes())
        throw_input("element " + std::to_string(e) + " refers to node " + std::to_string(n) +
                    ", which is not in the mesh");
      geometry_[e].X[a] = mesh.nodes[n];
      geometry_[e].D[a] = mesh.directors[n];
    }
  }
  build_pattern();
  colour_elements();
}

// Column of free dof c holds the free dofs of every node that shares an element with c's node.
void Assembler::build_pattern() {
  const int num_nodes = mesh_.num_nodes();
  std::vector<std::vector<int>> adjacent(num_nodes);
  for (const auto& el : mesh_.elements)
    for (int a : el)
      for (int b : el) adjacent[a].push_back(b);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  const int n = dofs_.num_free();
  std::vector<int> outer(n + 1, 0);
  std::vector<int> inner;
  for (int c = 0; c < n; ++c) {
    for (int m : adjacent[dofs_.free_dofs()[c] / kShellNodeDofs])
      for (int l = 0; l < kShellNodeDofs; ++l) {
        const int row = dofs_.equation(DofMap::dof(m, l));
        if (row >= 0) inner.push_back(row);
      }
    outer[c + 1] = static_cast<int>(inner.size());
  }
  pattern_.resize(n, n);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill_n(pattern_.valuePtr(), inner.size(), 0.0);

  slots_.assign(static_cast<std::size_t>(mesh_.num_elements()) * 400, -1);
  for (int e = 0; e < mesh_.num_elements(); ++e) {
    const ElementDofs d = DofMap::element_dofs(mesh_.elements[e]);
    for (int j = 0; j < 20; ++j) {
      const int col = dofs_.equation(d[j]);
      if (col < 0) continue;
      const int* begin = pattern_.innerIndexPtr() + outer[col];
      const int* end = pattern_.innerIndexPtr() + outer[col + 1];
      for (int i = 0; i < 20; ++i) {
        const int row = dofs_.equation(d[i]);
        if (row < 0) continue;
        slots_[400 * static_cast<std::size_t>(e) + 20 * i + j] =
            static_cast<int>(std::lower_bound(begin, end, row) - pattern_.innerIndexPtr());
      }
    }
  }
}

// Greedy colouring: each element takes the smallest colour not used by an element sharing a node.
void Assembler::colour_elements() {
  const int num_elements = mesh_.num_elements();
  std::vector<std::vector<int>> node_colours(mesh_.num_nodes());
  std::vector<int> colour(num_elements);
  int num_colours = 0;
  for (int e = 0; e < num_elements; ++e) {
    int c = 0;
    const auto used = [&](int cc) {
      for (int n : mesh_.elements[e])
        if (std::find(node_colours[n].begin(), node_colours[n].end(), cc) != node_colours[n].end())
          return true;
      return false;
    };
    while (used(c)) ++c;
    colour[e] = c;
    num_colours = std::max(num_colours, c + 1);
    for (int n : mesh_.elements[e]) node_colours[n].push_back(c);
  }
  colour_start_.assign(num_colours + 1, 0);
  for (int e = 0; e < num_elements; ++e) ++colour_start_[colour[e] + 1];
  for (int c = 0; c < num_colours; ++c) colour_start_[c + 1] += colour_start_[c];
  colour_order_.resize(num_elements);
  std::vector<int> next(colour_start_.begin(), colour_start_.end() - 1);
  for (int e = 0; e < num_elements; ++e) colour_order_[next[colour[e]]++] = e;
}

Assembly Assembler::make_assembly() const {
  Assembly a;
  a.tangent = pattern_;
  a.internal_force = Eigen::VectorXd::Zero(dofs_.num_dofs());
  return a;
}

std::array<NodeState, 4> Assembler::element_states(const std::vector<NodeState>& state,
                                                   int element) const {
  std::array<NodeState, 4> s;
  for (int a = 0; a < 4; ++a) s[a] = state[mesh_.elements[element][a]];
  return s;
}

void Assembler::add_element_block(int element, const Eigen::Matrix<double, 20, 20>& block,
                                  double scale, SparseMatrix& tangent) const {
  const int* slot = slots_.data() + 400 * static_cast<std::size_t>(element);
  double* values = tangent.valuePtr();
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      if (slot[20 * i + j] >= 0) values[slot[20 * i + j]] += scale * block(i, j);
}

void Assembler::compute_and_scatter(int e, const std::vector<NodeState>& state,
                                    const ElementRequest& request, ElementResponse& response,
                                    std::vector<double>& energy, Assembly& out) const {
  element_.compute(geometry_[e], element_states(state, e), law_, kinematics_, request, response);
  energy[e] = response.energy;
  if (request.force)
    DofMap::scatter_add(DofMap::element_dofs(mesh_.elements[e]), response.force,
                        out.internal_force);
  if (request.tangent) add_element_block(e, response.tangent, 1.0, out.tangent);
}

void Assembler::assemble(const std::vector<NodeState>& state, const ElementRequest& request,
                         Assembly& out) const {
  SI_REQUIRE(static_cast<int>(state.size()) == mesh_.num_nodes(),
             "assembly needs one nodal state per node");
  SI_ASSERT(out.tangent.nonZeros() == pattern_.nonZeros());
  if (request.tangent) std::fill_n(out.tangent.valuePtr(), out.tangent.nonZeros(), 0.0);
  if (request.force) out.internal_force.setZero();
  std::vector<double> energy(mesh_.num_elements(), 0.0);
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();

  // One parallel region; the implicit barrier after each colour's loop keeps colours apart.
  // An exception must not leave an OpenMP region (std::terminate): the first one is kept and
  // rethrown after the region; the other threads skip their remaining elements.
  std::exception_ptr failure;
  bool failed = false;
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    ElementResponse response;  // this thread's buffer
    for (int c = 0; c < num_colours(); ++c) {
#pragma omp for schedule(static)
      for (int k = colour_start_[c]; k < colour_start_[c + 1]; ++k) {
        bool skip;
#pragma omp atomic read
        skip = failed;
        if (skip) continue;
        try {
          compute_and_scatter(colour_order_[k], state, request, response, energy, out);
        } catch (...) {
#pragma omp critical(si_assembly_failure)
          if (!failure) failure = std::current_exception();
#pragma omp atomic write
          failed = true;
        }
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
  out.energy = 0;
  for (double w : energy) out.energy += w;
}

Eigen::VectorXd reactions(const DofMap& dofs, const Eigen::VectorXd& internal_force,
                          const Eigen::VectorXd& external_force) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.num_dofs());
  for (int dof : dofs.prescribed_dofs()) r[dof] = internal_force[dof] - external_force[dof];
  return r;
}

std::vector<NodeState> reference_state(const Mesh& mesh) {
  std::vector<NodeState> s;
  s.reserve(mesh.directors.size());
  for (const Vector3d& D : mesh.directors) s.push_back(reference_node_state(D));
  return s;
}

}  // namespace si
