#pragma once
// A check of a recording before leaving the field: every message of a type littermap knows is
// decoded (bag/message_stream.hpp), images included, so a damaged one is found now rather than by
// a later stage.

#include <cstdint>
#include <string>
#include <vector>

#include "bag/bag_reader.hpp"
#include "core/progress.hpp"

namespace littermap::bag {

struct VerifyResult {
  std::uint64_t decoded_messages = 0;  // messages of known types, all of which decoded
  std::uint64_t decoded_images = 0;    // of which images, their pixels decoded too
  std::vector<std::string> warnings;   // one per topic of a type littermap does not use
  // Damage read past (BagReader::damage): a corrupt MCAP chunk, a cut-off file, each naming file
  // and offset. Their messages were not decoded; the rest was.
  std::vector<std::string> damage;
};

// Decodes every message from the reader's current position, reporting progress ("verifying")
// against the bag's message count. The first message that does not decode is a BadInputError
// naming the bag, topic and message index; so is an image whose pixels do not decode (JPEG, PNG,
// raw) or whose size differs from the last camera info of its camera ("/cam/color/image_raw/
// compressed" goes with "/cam/color/camera_info").
VerifyResult VerifyMessages(BagReader& reader, const ProgressCallback& progress = {});

}  // namespace littermap::bag
