// Numbers packed as their bytes, to send results between processes exactly: a double read back
// is the same double, bit for bit (no decimal printing). Both ends run the same binary, so the
// byte order and sizes agree.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace drape {

class ByteWriter {
 public:
  void Int(int64_t value) { Append(&value, sizeof value); }
  void Double(double value) { Append(&value, sizeof value); }
  void Doubles(const std::vector<double>& values) {
    Int(static_cast<int64_t>(values.size()));
    Append(values.data(), values.size() * sizeof(double));
  }
  void Text(const std::string& text) {
    Int(static_cast<int64_t>(text.size()));
    bytes_ += text;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void Append(const void* data, size_t size) {
    bytes_.append(static_cast<const char*>(data), size);
  }
  std::string bytes_;
};

// Reads what a ByteWriter wrote, in the same order; reading past the end is a programmer error
// (std::logic_error).
class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  int64_t Int() { return Read<int64_t>(); }
  double Double() { return Read<double>(); }
  std::vector<double> Doubles() {
    std::vector<double> values(static_cast<size_t>(Int()));
    Take(values.data(), values.size() * sizeof(double));
    return values;
  }
  std::string Text() {
    std::string text(static_cast<size_t>(Int()), '\0');
    Take(text.data(), text.size());
    return text;
  }
  bool AtEnd() const { return offset_ == bytes_.size(); }

 private:
  template <typename T>
  T Read() {
    T value;
    Take(&value, sizeof value);
    return value;
  }
  void Take(void* data, size_t size) {
    if (offset_ + size > bytes_.size()) throw std::logic_error("ByteReader: read past the end");
    if (size == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    std::memcpy(data, bytes_.data() + offset_, size);
    offset_ += size;
  }
  const std::string& bytes_;
  size_t offset_ = 0;
};

}  // namespace drape
