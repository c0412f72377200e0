// Where a scene schema row's value goes: a member of the struct its table is read into
// (SolverSpec::tolerance for `solver.tolerance`). The loader sets it from the scene file,
// scene.yaml is written from it, and the row's default is the member's value in a
// default-constructed struct, so a default is stated once, in src/scene/scene.h.
#ifndef DRAPE_SRC_SCENE_SCENE_FIELD_H_
#define DRAPE_SRC_SCENE_SCENE_FIELD_H_

#include <Eigen/Core>
#include <cassert>
#include <functional>
#include <optional>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <variant>

namespace drape {

// A row's value, typed: none (an optional member not given), a number, a whole number, a truth
// value, a word or text, a point, a pair.
using FieldValue =
    std::variant<std::monostate, double, int, bool, std::string, Eigen::Vector3d, Eigen::Vector2d>;

// The member a row binds: its owner's type (checked by assertion where it is used) and how to set
// and get it through a pointer to the owner.
struct SceneField {
  std::type_index owner = typeid(void);
  std::function<void(void*, const FieldValue&)> set;
  std::function<FieldValue(const void*)> get;

  explicit operator bool() const { return static_cast<bool>(set); }
};

namespace scene_field_internal {

template <typename T>
void Assign(T* member, const FieldValue& value) {
  assert(std::holds_alternative<T>(value) && "a row's value of another type than its member");
  *member = std::get<T>(value);
}
template <typename T>
void Assign(std::optional<T>* member, const FieldValue& value) {
  if (std::holds_alternative<std::monostate>(value)) {
    member->reset();
  } else {
    *member = std::get<T>(value);
  }
}
template <typename T>
FieldValue Value(const T& member) {
  return member;
}
template <typename T>
FieldValue Value(const std::optional<T>& member) {
  return member ? FieldValue(*member) : FieldValue();
}

}  // namespace scene_field_internal

// The binding of `member` of `Owner`.
template <typename Owner, typename T>
SceneField FieldOf(T Owner::*member) {
  SceneField field;
  field.owner = typeid(Owner);
  field.set = [member](void* owner, const FieldValue& value) {
    scene_field_internal::Assign(&(static_cast<Owner*>(owner)->*member), value);
  };
  field.get = [member](const void* owner) {
    return scene_field_internal::Value(static_cast<const Owner*>(owner)->*member);
  };
  return field;
}

// The value as the reference and scene.yaml write it: 0.001, 15, true, xy, [0, 0, 0]; "" for none.
std::string FieldValueText(const FieldValue& value);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_FIELD_H_
