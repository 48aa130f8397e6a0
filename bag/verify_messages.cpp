#include "bag/verify_messages.hpp"

#include "bag/message_stream.hpp"

namespace littermap::bag {
namespace {

constexpr std::uint64_t kProgressEvery = 256;  // messages between progress reports

}  // namespace

VerifyResult VerifyMessages(BagReader& reader, const ProgressCallback& progress) {
  reader.SetVerifyChecksums(true);
  MessageStream stream(reader);
  const std::uint64_t total = reader.info().message_count;
  VerifyResult result;
  while (stream.Next()) {
    ++result.decoded_messages;
    if (result.decoded_messages % kProgressEvery == 0) {
      ReportProgress(progress, {"verifying", result.decoded_messages, total});
    }
  }
  result.warnings = stream.warnings();
  result.damage = reader.damage();
  return result;
}

}  // namespace littermap::bag
