#include "src/parallel/farm_record.h"

#include "src/parallel/byte_codec.h"

namespace drape {

std::string EncodeFarmRecords(const std::vector<FarmRecord>& records) {
  ByteWriter writer;
  writer.Int(static_cast<int64_t>(records.size()));
  for (const FarmRecord& record : records) {
    writer.Text(record.kind);
    writer.Int(record.task);
    writer.Text(record.row);
    writer.Doubles(record.numbers);
  }
  return writer.bytes();
}

std::vector<FarmRecord> DecodeFarmRecords(const std::string& text) {
  ByteReader reader(text);
  std::vector<FarmRecord> records(static_cast<size_t>(reader.Int()));
  for (FarmRecord& record : records) {
    record.kind = reader.Text();
    record.task = static_cast<int>(reader.Int());
    record.row = reader.Text();
    record.numbers = reader.Doubles();
  }
  if (!reader.AtEnd()) throw std::logic_error("farm records: bytes left after the last record");
  return records;
}

}  // namespace drape
