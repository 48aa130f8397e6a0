#include "bag/cdr.hpp"

#include <limits>

namespace littermap::cdr {
namespace {

constexpr std::uint8_t kEncapsulationCdrLe = 0x01;

std::string Hex(std::uint8_t byte) {
  constexpr char kDigits[] = "0123456789abcdef";
  return {'0', 'x', kDigits[byte >> 4], kDigits[byte & 0x0f]};
}

}  // namespace

Writer::Writer(std::size_t reserve_bytes) {
  buffer_.reserve(reserve_bytes + kHeaderSize);
  buffer_ = {0x00, kEncapsulationCdrLe, 0x00, 0x00};
}

void Writer::WriteString(std::string_view value) {
  Write<std::uint32_t>(CheckedCount(value.size() + 1));
  Append(value.data(), value.size());
  buffer_.push_back(0);
}

void Writer::Align(std::size_t alignment) {
  const std::size_t misalignment = (buffer_.size() - kHeaderSize) % alignment;
  if (misalignment != 0) buffer_.resize(buffer_.size() + alignment - misalignment, 0);
}

void Writer::Append(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  buffer_.insert(buffer_.end(), bytes, bytes + size);
}

std::uint32_t Writer::CheckedCount(std::size_t count) {
  if (count > std::numeric_limits<std::uint32_t>::max()) {
    throw InternalError("CDR: sequence of " + std::to_string(count) + " elements is too long");
  }
  return static_cast<std::uint32_t>(count);
}

Reader::Reader(std::span<const std::uint8_t> data) : data_(data) {
  if (data_.size() < kHeaderSize) {
    throw CdrError("CDR: message of " + std::to_string(data_.size()) +
                   " bytes is shorter than the 4-byte encapsulation header");
  }
  if (data_[0] != 0x00 || data_[1] != kEncapsulationCdrLe) {
    throw CdrError("CDR: unsupported encapsulation " + Hex(data_[0]) + " " + Hex(data_[1]) +
                   " (only little-endian plain CDR, 0x00 0x01)");
  }
}

bool Reader::ReadBool(const char* field) {
  const auto value = Read<std::uint8_t>(field);
  if (value > 1) {
    throw CdrError("CDR: field '" + std::string(field) + "' at byte " +
                   std::to_string(offset_ - 1) + " is not a boolean (" + std::to_string(value) +
                   ")");
  }
  return value == 1;
}

std::string Reader::ReadString(const char* field) {
  const std::uint32_t length = ReadCount(1, field);
  if (length == 0) return {};  // some writers emit a zero length for an empty string
  Require(length, field);
  const char* begin = reinterpret_cast<const char*>(data_.data() + offset_);
  if (begin[length - 1] != '\0') {
    throw CdrError("CDR: string '" + std::string(field) + "' at byte " + std::to_string(offset_) +
                   " is not NUL-terminated");
  }
  offset_ += length;
  return std::string(begin, length - 1);
}

std::uint32_t Reader::ReadCount(std::size_t min_element_bytes, const char* field) {
  const auto count = Read<std::uint32_t>(field);
  // Divide rather than multiply: count * min_element_bytes can overflow a 32-bit size_t.
  if (min_element_bytes != 0 && count > remaining() / min_element_bytes) {
    throw CdrError("CDR: '" + std::string(field) + "' claims " + std::to_string(count) +
                   " elements at byte " + std::to_string(offset_ - 4) + " but only " +
                   std::to_string(remaining()) + " bytes are left");
  }
  return count;
}

void Reader::Align(std::size_t alignment, const char* field) {
  const std::size_t misalignment = (offset_ - kHeaderSize) % alignment;
  if (misalignment == 0) return;
  const std::size_t padding = alignment - misalignment;
  Require(padding, field);
  offset_ += padding;
}

void Reader::Require(std::size_t bytes, const char* field) const {
  if (bytes > remaining()) {
    throw CdrError("CDR: truncated at byte " + std::to_string(offset_) + " reading '" +
                   std::string(field) + "' (needs " + std::to_string(bytes) + " bytes, " +
                   std::to_string(remaining()) + " left)");
  }
}

}  // namespace littermap::cdr
