// Spring models built directly in tests (without a scene file): a rectangular sheet and a chain,
// in whatever consistent units the caller chooses. Used by the newton, stability and hard-case
// tests to exercise the solver independently of scene loading.
#ifndef DRAPE_TESTS_HAND_BUILT_MODELS_H_
#define DRAPE_TESTS_HAND_BUILT_MODELS_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "costs/constant_force_potential.h"
#include "costs/spring_stretch.h"
#include "costs/tension_only_spring.h"
#include "src/model/model.h"

namespace drape::testing {

struct SpringNetwork {
  double structural = 1000.0;  // stiffness per spring (force/length); 0: family not built
  double shear = 500.0;
  double flexion = 10.0;
  bool tension_only = false;
};

struct SheetSpec {
  int nu = 15, nv = 15;  // nodes along x and y
  double width = 1.0, height = 1.0;
  double density = 0.2;  // mass per area
  SpringNetwork springs;
  std::array<double, 3> gravity{0.0, 0.0, -9.81};
  std::vector<int> fixed;                                     // fully fixed node ids
  std::vector<std::pair<int, std::array<double, 3>>> forces;  // applied force on a node
};

inline int GridId(const SheetSpec& spec, int i, int j) { return j * spec.nu + i; }

namespace internal {

inline void AddSpring(Model* model, const char* type, double stiffness, bool tension_only, int a,
                      int b) {
  if (stiffness <= 0.0) return;
  const double* pa = &model->initial[3 * a];
  const double* pb = &model->initial[3 * b];
  const double rest =
      std::sqrt((pa[0] - pb[0]) * (pa[0] - pb[0]) + (pa[1] - pb[1]) * (pa[1] - pb[1]) +
                (pa[2] - pb[2]) * (pa[2] - pb[2]));
  if (tension_only) {
    model->terms.push_back(MakeTerm(type, {a, b}, TensionOnlySpring::Create(stiffness, rest)));
  } else {
    model->terms.push_back(MakeTerm(type, {a, b}, SpringStretch::Create(stiffness, rest)));
  }
}

// Gravity and applied forces as constant-force potentials; fills model.applied.
inline void AddLoads(Model* model, const std::array<double, 3>& gravity,
                     const std::vector<std::pair<int, std::array<double, 3>>>& forces) {
  model->applied.assign(model->num_dofs(), 0.0);
  for (int node = 0; node < model->num_nodes; ++node) {
    const double weight[3] = {model->mass[node] * gravity[0], model->mass[node] * gravity[1],
                              model->mass[node] * gravity[2]};
    if (weight[0] == 0.0 && weight[1] == 0.0 && weight[2] == 0.0) continue;
    model->terms.push_back(MakeTerm(
        "gravity", {node}, ConstantForcePotential::Create(weight, &model->initial[3 * node])));
    for (int c = 0; c < 3; ++c) model->applied[3 * node + c] += weight[c];
  }
  for (const auto& [node, force] : forces) {
    model->terms.push_back(MakeTerm(
        "force", {node}, ConstantForcePotential::Create(force.data(), &model->initial[3 * node])));
    for (int c = 0; c < 3; ++c) model->applied[3 * node + c] += force[c];
  }
}

inline void Finish(Model* model, const std::vector<int>& fixed) {
  model->fixed.assign(model->num_dofs(), 0);
  for (int node : fixed) std::fill_n(&model->fixed[3 * node], 3, 1);
  model->positions = model->initial;
  ValidateModel(*model);
}

}  // namespace internal

// A flat sheet in the xy plane, node (i, j) at (i·width/(nu−1), j·height/(nv−1), 0), with
// structural, shear-diagonal and skip-one flexion springs at their initial lengths and masses
// lumped by area (quarter cells at corners).
inline Model Sheet(const SheetSpec& spec) {
  Model model;
  model.num_nodes = spec.nu * spec.nv;
  const double du = spec.width / (spec.nu - 1), dv = spec.height / (spec.nv - 1);
  model.grid_index.resize(model.num_nodes);
  model.mass.assign(model.num_nodes, 0.0);
  for (int j = 0; j < spec.nv; ++j) {
    for (int i = 0; i < spec.nu; ++i) {
      model.initial.insert(model.initial.end(), {i * du, j * dv, 0.0});
      const int id = GridId(spec, i, j);
      model.grid_index[id] = {i, j};
      const double wu = (i == 0 || i == spec.nu - 1) ? 0.5 : 1.0;
      const double wv = (j == 0 || j == spec.nv - 1) ? 0.5 : 1.0;
      model.mass[id] = spec.density * du * dv * wu * wv;
    }
  }
  model.size = std::hypot(spec.width, spec.height);
  const SpringNetwork& k = spec.springs;
  for (int j = 0; j < spec.nv; ++j) {
    for (int i = 0; i < spec.nu; ++i) {
      const int id = GridId(spec, i, j);
      if (i + 1 < spec.nu)
        internal::AddSpring(&model, "structural", k.structural, k.tension_only, id, id + 1);
      if (j + 1 < spec.nv)
        internal::AddSpring(&model, "structural", k.structural, k.tension_only, id, id + spec.nu);
      if (i + 1 < spec.nu && j + 1 < spec.nv) {
        internal::AddSpring(&model, "shear", k.shear, k.tension_only, id, id + spec.nu + 1);
        internal::AddSpring(&model, "shear", k.shear, k.tension_only, id + 1, id + spec.nu);
      }
      if (i + 2 < spec.nu)
        internal::AddSpring(&model, "flexion", k.flexion, k.tension_only, id, id + 2);
      if (j + 2 < spec.nv)
        internal::AddSpring(&model, "flexion", k.flexion, k.tension_only, id, id + 2 * spec.nu);
    }
  }
  internal::AddLoads(&model, spec.gravity, spec.forces);
  internal::Finish(&model, spec.fixed);
  return model;
}

struct ChainSpec {
  int nodes = 11;
  double length = 1.0;  // distance between the supports; nodes start evenly along x
  double stiffness = 50.0;
  double rest_length = -1.0;  // per spring; < 0: the initial spacing
  double flexion = 0.0;       // skip-one springs
  double node_mass = 0.01;
  std::array<double, 3> gravity{0.0, 0.0, -9.81};
  bool planar = false;  // y fixed everywhere (dimension 2)
};

// A straight chain along x with both ends fixed; springs of the given rest length (a chain
// shorter than its rest length starts compressed, one longer starts stretched).
inline Model Chain(const ChainSpec& spec) {
  Model model;
  model.num_nodes = spec.nodes;
  const double spacing = spec.length / (spec.nodes - 1);
  const double rest = spec.rest_length > 0.0 ? spec.rest_length : spacing;
  for (int n = 0; n < spec.nodes; ++n)
    model.initial.insert(model.initial.end(), {n * spacing, 0.0, 0.0});
  model.mass.assign(spec.nodes, spec.node_mass);
  model.grid_index.assign(spec.nodes, {-1, -1});
  model.size = spec.length;
  for (int n = 0; n + 1 < spec.nodes; ++n) {
    model.terms.push_back(
        MakeTerm("structural", {n, n + 1}, SpringStretch::Create(spec.stiffness, rest)));
  }
  for (int n = 0; n + 2 < spec.nodes && spec.flexion > 0.0; ++n) {
    model.terms.push_back(
        MakeTerm("flexion", {n, n + 2}, SpringStretch::Create(spec.flexion, 2 * rest)));
  }
  internal::AddLoads(&model, spec.gravity, {});
  internal::Finish(&model, {0, spec.nodes - 1});
  if (spec.planar) {
    for (int n = 0; n < spec.nodes; ++n) model.fixed[3 * n + 1] = 1;
  }
  return model;
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_HAND_BUILT_MODELS_H_
