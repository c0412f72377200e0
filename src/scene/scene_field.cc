#include "src/scene/scene_field.h"

#include "src/scene/number_text.h"

namespace drape {

std::string FieldValueText(const FieldValue& value) {
  struct Text {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(double number) const { return FormatNumber(number); }
    std::string operator()(int number) const { return std::to_string(number); }
    std::string operator()(bool truth) const { return truth ? "true" : "false"; }
    std::string operator()(const std::string& word) const { return word; }
    std::string operator()(const Eigen::Vector3d& v) const { return List(v.data(), 3); }
    std::string operator()(const Eigen::Vector2d& v) const { return List(v.data(), 2); }
    static std::string List(const double* values, int count) {
      std::string text = "[";
      for (int k = 0; k < count; ++k) text += (k == 0 ? "" : ", ") + FormatNumber(values[k]);
      return text + "]";
    }
  };
  return std::visit(Text{}, value);
}

}  // namespace drape
