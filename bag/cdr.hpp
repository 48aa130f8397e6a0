#pragma once
// OMG CDR (XCDR1, "plain CDR") as ROS 2 serialises messages with Fast DDS / Cyclone DDS:
// a 4-byte encapsulation header {0x00, 0x01 (CDR_LE), 0x00, 0x00}, then the fields in
// declaration order, each primitive aligned to its own size (1, 2, 4 or 8 bytes) relative to the
// first byte after the header. A string is a uint32 length that counts the terminating NUL, the
// bytes and the NUL. A sequence is a uint32 element count followed by the elements; a fixed
// array has no count. (OMG DDS-XTypes 1.3, 7.4.3.5 "XCDR stream format version 1".)

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/error.hpp"

namespace littermap::cdr {

inline constexpr std::size_t kHeaderSize = 4;

// Malformed CDR: truncated, bad header, impossible lengths. Names the field and byte offset.
class CdrError : public BadInputError {
 public:
  using BadInputError::BadInputError;
};

class Writer {
 public:
  explicit Writer(std::size_t reserve_bytes = 256);

  template <typename T>
  void Write(T value) {
    static_assert(std::is_arithmetic_v<T>);
    Align(sizeof(T));
    Append(&value, sizeof(T));
  }
  void WriteBool(bool value) { Write<std::uint8_t>(value ? 1 : 0); }
  void WriteString(std::string_view value);

  // A sequence of primitives: count, then the elements aligned to their size.
  template <typename T>
  void WriteSequence(std::span<const T> values) {
    static_assert(std::is_arithmetic_v<T>);
    Write<std::uint32_t>(CheckedCount(values.size()));
    WriteArray(values);
  }
  // A fixed-size array of primitives: the elements only.
  template <typename T>
  void WriteArray(std::span<const T> values) {
    static_assert(std::is_arithmetic_v<T>);
    if (values.empty()) return;
    Align(sizeof(T));
    Append(values.data(), values.size_bytes());
  }
  void WriteCount(std::size_t count) { Write<std::uint32_t>(CheckedCount(count)); }

  std::size_t size() const { return buffer_.size(); }
  std::vector<std::uint8_t> Take() { return std::move(buffer_); }

 private:
  void Align(std::size_t alignment);
  void Append(const void* data, std::size_t size);
  static std::uint32_t CheckedCount(std::size_t count);

  std::vector<std::uint8_t> buffer_;
};

class Reader {
 public:
  // Checks the encapsulation header; throws CdrError if it is missing or not little-endian CDR.
  explicit Reader(std::span<const std::uint8_t> data);

  template <typename T>
  T Read(const char* field) {
    static_assert(std::is_arithmetic_v<T>);
    Align(sizeof(T), field);
    Require(sizeof(T), field);
    T value;
    std::memcpy(&value, data_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return value;
  }
  bool ReadBool(const char* field);
  std::string ReadString(const char* field);

  template <typename T>
  std::vector<T> ReadSequence(const char* field) {
    const std::uint32_t count = ReadCount(sizeof(T), field);
    std::vector<T> values(count);
    ReadArray(std::span<T>(values), field);
    return values;
  }
  template <typename T>
  void ReadArray(std::span<T> out, const char* field) {
    static_assert(std::is_arithmetic_v<T>);
    if (out.empty()) return;
    Align(sizeof(T), field);
    Require(out.size_bytes(), field);
    std::memcpy(out.data(), data_.data() + offset_, out.size_bytes());
    offset_ += out.size_bytes();
  }
  // A sequence length, checked against the bytes left assuming each element takes at least
  // min_element_bytes, so a corrupt count cannot make the caller allocate gigabytes.
  std::uint32_t ReadCount(std::size_t min_element_bytes, const char* field);

  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return data_.size() - offset_; }

 private:
  void Align(std::size_t alignment, const char* field);
  void Require(std::size_t bytes, const char* field) const;

  std::span<const std::uint8_t> data_;
  std::size_t offset_ = kHeaderSize;
};

}  // namespace littermap::cdr
