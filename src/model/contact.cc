#include "src/model/contact.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "costs/box_contact.h"
#include "costs/cylinder_contact.h"
#include "costs/disk_contact.h"
#include "costs/plane_contact.h"
#include "costs/sphere_contact.h"

namespace drape {

namespace {

const char* KindName(ObstacleSpec::Kind kind) {
  switch (kind) {
    case ObstacleSpec::Kind::kSphere:
      return "sphere";
    case ObstacleSpec::Kind::kDisk:
      return "disk";
    case ObstacleSpec::Kind::kCylinder:
      return "cylinder";
    case ObstacleSpec::Kind::kBox:
      return "box";
    case ObstacleSpec::Kind::kPlane:
      return "plane";
    case ObstacleSpec::Kind::kPin:
      return "pin";
  }
  return "obstacle";
}

// Calls `visit` with the obstacle's contact functor.
template <typename Visitor>
auto WithFunctor(const ObstacleSpec& o, double clearance, double stiffness, Visitor visit) {
  switch (o.kind) {
    case ObstacleSpec::Kind::kSphere:
    case ObstacleSpec::Kind::kPin:  // a point support: a sphere of radius 0 (see sphere_contact.h)
      return visit(SphereContact::Create(o.center.data(),
                                         o.kind == ObstacleSpec::Kind::kPin ? 0.0 : o.radius,
                                         clearance, stiffness));
    case ObstacleSpec::Kind::kDisk:
      return visit(DiskContact::Create(o.center.data(), o.radius, clearance, stiffness));
    case ObstacleSpec::Kind::kCylinder:
      return visit(
          CylinderContact::Create(o.center.data(), o.radius, o.height, clearance, stiffness));
    case ObstacleSpec::Kind::kBox:
      return visit(BoxContact::Create(o.min.data(), o.max.data(), clearance, stiffness));
    case ObstacleSpec::Kind::kPlane:
      break;
  }
  return visit(PlaneContact::Create(o.center.data(), o.normal.data(), clearance, stiffness));
}

bool FullyFixed(const Model& model, int node) {
  return model.fixed[3 * node] && model.fixed[3 * node + 1] && model.fixed[3 * node + 2];
}

void CheckContactInput(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact) {
  for (const ObstacleSpec& obstacle : obstacles) {
    if (obstacle.friction > 0.0) {
      throw InputError(obstacle.where, "friction is not supported yet: obstacles are frictionless");
    }
  }
  if (!obstacles.empty() && !(contact.thickness > 0.0)) {
    const Location& where = contact.where.line > 0 ? contact.where : obstacles.front().where;
    throw InputError(where, "contact.thickness must be positive when there are obstacles");
  }
}

}  // namespace

double ContactStiffness(const ContactSpec& contact, const Model& model) {
  double reference = 0.0;
  for (int k = 0; k < model.num_nodes; ++k) {
    reference += std::sqrt(model.applied[3 * k] * model.applied[3 * k] +
                           model.applied[3 * k + 1] * model.applied[3 * k + 1] +
                           model.applied[3 * k + 2] * model.applied[3 * k + 2]);
  }
  if (!(reference > 0.0)) reference = 1.0;
  const double allowed = kAllowedPenetration * contact.thickness;
  return reference / (allowed * allowed);
}

double ObstacleDistance(const ObstacleSpec& obstacle, const double* x) {
  return WithFunctor(obstacle, 0.0, 0.0, [x](const auto& functor) { return functor.Distance(x); });
}

void AddContactTerms(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                     Model* model) {
  CheckContactInput(obstacles, contact);
  if (obstacles.empty()) return;
  const double stiffness = ContactStiffness(contact, *model);
  bool anchored = false;
  for (int k = 0; k < model->num_nodes; ++k) anchored = anchored || FullyFixed(*model, k);
  const double reach = kReachFactor * model->size;
  // Least-squares shift of the potential (src/model/term.h): the energy at a full clearance's depth.
  const double shift = stiffness * std::pow(contact.thickness, 3) / 3.0;
  for (const ObstacleSpec& obstacle : obstacles) {
    const std::string type = std::string(KindName(obstacle.kind)) + "_contact";
    for (int k = 0; k < model->num_nodes; ++k) {
      if (FullyFixed(*model, k)) continue;
      const double* x = model->positions.data() + 3 * k;
      if (anchored && ObstacleDistance(obstacle, x) - contact.thickness > reach) continue;
      WithFunctor(obstacle, contact.thickness, stiffness, [&](const auto& functor) {
        model->terms.push_back(MakeTerm(type, {k}, functor, shift));
        return 0;
      });
    }
  }
}

ContactReport MeasureContact(const std::vector<ObstacleSpec>& obstacles, const ContactSpec& contact,
                             const Model& model, const double* positions) {
  ContactReport report;
  report.thickness = contact.thickness;
  if (obstacles.empty()) return report;
  report.stiffness = ContactStiffness(contact, model);
  for (const auto& term : model.terms) {
    const std::string& type = term->type();
    const std::string suffix = "_contact";
    if (type.size() > suffix.size() &&
        type.compare(type.size() - suffix.size(), suffix.size(), suffix) == 0) {
      ++report.terms;
    }
  }
  for (int k = 0; k < model.num_nodes; ++k) {
    double deepest = 0.0;
    for (const ObstacleSpec& obstacle : obstacles) {
      deepest =
          std::max(deepest, contact.thickness - ObstacleDistance(obstacle, positions + 3 * k));
    }
    if (deepest > 0.0) ++report.nodes_in_contact;
    report.max_penetration = std::max(report.max_penetration, deepest);
  }
  if (contact.thickness > 0.0) {
    report.max_penetration_fraction = report.max_penetration / contact.thickness;
  }
  return report;
}

}  // namespace drape
