#include "src/scene/schema_reader.h"

#include <cassert>
#include <vector>

namespace drape {
namespace {

double Checked(const SchemaRow& row, const YamlValue& value, double number) {
  if (row.bounds && !row.bounds->Contains(number)) Fail(value, row.bounds->Refusal(number));
  return number;
}

}  // namespace

FieldValue ReadRowValue(const SchemaRow& row, const YamlValue& value) {
  switch (row.value) {
    case ValueType::kNumber:
      return Checked(row, value, ReadNumber(value));
    case ValueType::kInteger:
      return static_cast<int>(Checked(row, value, ReadInt(value)));
    case ValueType::kBool:
      return ReadBool(value);
    case ValueType::kWord:
      return ReadChoice(value, row.words);
    case ValueType::kText:
      return ReadString(value);
    case ValueType::kPoint:
      return ReadVector3(value);
    case ValueType::kPair: {
      const std::vector<double> xy = ReadNumbers(value, 2);
      return Eigen::Vector2d(xy[0], xy[1]);
    }
    case ValueType::kOther:
      break;
  }
  assert(false && "a composite row is read by the loader's code");
  return {};
}

double ReadRowNumber(const YamlValue& value) {
  const SchemaRow* row = SchemaRowAt(value.where.key);
  assert(row && "ReadRowNumber of a value without its schema row");
  return Checked(*row, value, ReadNumber(value));
}

void ReadFieldsOf(const YamlMap& map, const std::string& table, const std::string& kind,
                  std::type_index owner_type, void* owner) {
  for (const SchemaRow* row : SchemaRows(table)) {
    if (!row->field || row->field.owner != owner_type || !row->Takes(kind)) continue;
    if (const auto given = map.Find(row->key)) row->field.set(owner, ReadRowValue(*row, *given));
  }
}

}  // namespace drape
