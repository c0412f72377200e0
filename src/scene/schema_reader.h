// Reading a scene's plain values through their schema rows (src/scene/scene_schema.h): each value
// is read as its row's type, checked against its row's range or words, and stored in the member
// its row binds. The loader's code reads only the composite values and the cross-key rules.
#ifndef DRAPE_SRC_SCENE_SCHEMA_READER_H_
#define DRAPE_SRC_SCENE_SCHEMA_READER_H_

#include <string>
#include <typeindex>

#include "src/scene/scene_schema.h"
#include "src/scene/yaml_reader.h"

namespace drape {

// The value at `value` as `row` types and bounds it; a located InputError otherwise.
FieldValue ReadRowValue(const SchemaRow& row, const YamlValue& value);

// A number checked against the range of its row, found by the value's path
// (src/scene/scene_schema.h SchemaRowAt): for a value the loader's code reads, converts or
// combines (kes.B_warp, a region's D_warp, a spring family's warp).
double ReadRowNumber(const YamlValue& value);

// Every key of `map` whose row in `table` (for `kind`, "" any) binds a member of `owner`'s type:
// read, checked and stored there. Other keys are left to the caller.
void ReadFieldsOf(const YamlMap& map, const std::string& table, const std::string& kind,
                  std::type_index owner_type, void* owner);

template <typename Owner>
void ReadFields(const YamlMap& map, const std::string& table, Owner* owner,
                const std::string& kind = "") {
  ReadFieldsOf(map, table, kind, typeid(Owner), owner);
}

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCHEMA_READER_H_
