#include "importers/tum_sequence.hpp"

#include <algorithm>
#include <string>
#include <tuple>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace littermap::importers {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view NextToken(std::string_view* rest) {
  std::size_t begin = 0;
  while (begin < rest->size() && IsBlank((*rest)[begin])) ++begin;
  std::size_t end = begin;
  while (end < rest->size() && !IsBlank((*rest)[end])) ++end;
  const std::string_view token = rest->substr(begin, end - begin);
  rest->remove_prefix(end);
  return token;
}

TumFrameEntry ParseFrameLine(std::string_view line) {
  TumFrameEntry entry;
  const std::string_view stamp = NextToken(&line);
  if (!bag::ParseTumStamp(stamp, &entry.stamp_ns)) {
    throw BadInputError("field 'timestamp': '" + std::string(stamp) + "' is not a time");
  }
  const std::string_view file = NextToken(&line);
  if (file.empty()) throw BadInputError("field 'filename' is missing");
  if (!NextToken(&line).empty()) throw BadInputError("unexpected fields after 'filename'");
  entry.file = std::filesystem::path(std::string(file));
  if (entry.file.is_absolute()) {
    throw BadInputError("field 'filename': '" + std::string(file) +
                        "' must be relative to the sequence directory");
  }
  return entry;
}

}  // namespace

std::vector<TumFrameEntry> ReadTumFrameList(const std::filesystem::path& path) {
  TextLineReader reader(path);
  std::vector<TumFrameEntry> entries;
  std::string_view line;
  while (reader.Next(&line)) {
    std::string_view probe = line;
    const std::string_view first = NextToken(&probe);
    if (first.empty() || first[0] == '#') continue;
    try {
      entries.push_back(ParseFrameLine(line));
    } catch (const BadInputError& error) {
      throw BadInputError(path.string() + ":" + std::to_string(reader.line_number()) + ": " +
                          error.what());
    }
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b) { return a.stamp_ns < b.stamp_ns; });
  return entries;
}

std::vector<TumFramePair> AssociateTumFrames(const std::vector<TumFrameEntry>& colour,
                                             const std::vector<TumFrameEntry>& depth,
                                             double max_gap_s) {
  const TimestampNs max_gap_ns = FromSeconds(max_gap_s);
  // Candidates (gap, colour, depth); depth is sorted, so each colour frame's candidates are a
  // contiguous range found by binary search.
  std::vector<std::tuple<TimestampNs, std::size_t, std::size_t>> candidates;
  for (std::size_t c = 0; c < colour.size(); ++c) {
    const TimestampNs t = colour[c].stamp_ns;
    auto it = std::lower_bound(depth.begin(), depth.end(), t - max_gap_ns,
                               [](const auto& entry, TimestampNs s) { return entry.stamp_ns < s; });
    for (; it != depth.end() && it->stamp_ns <= t + max_gap_ns; ++it) {
      const TimestampNs gap = std::abs(it->stamp_ns - t);
      if (gap < max_gap_ns) {
        candidates.emplace_back(gap, c, static_cast<std::size_t>(it - depth.begin()));
      }
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> colour_used(colour.size(), false);
  std::vector<bool> depth_used(depth.size(), false);
  std::vector<TumFramePair> pairs;
  for (const auto& [gap, c, d] : candidates) {
    if (colour_used[c] || depth_used[d]) continue;
    colour_used[c] = depth_used[d] = true;
    pairs.push_back({c, d});
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const auto& a, const auto& b) { return a.colour_index < b.colour_index; });
  return pairs;
}

}  // namespace littermap::importers
