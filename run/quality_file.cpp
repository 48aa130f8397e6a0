#include "run/quality_file.hpp"

#include <fstream>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"

namespace littermap::run {
namespace {

// Keys keep the order they are written in, as the file always had it.
using Json = nlohmann::ordered_json;

Json LandmarksJson(const LandmarkQuality& l) {
  return {{"in_graph", l.in_graph},
          {"sightings", l.sightings},
          {"associated_by_tracking", l.associated_by_tracking},
          {"loops_found", l.loops_found},
          {"loops_accepted", l.loops_accepted},
          {"loops_rejected", l.loops_rejected}};
}

Json ScanAlignmentJson(const ScanAlignmentQuality& a) {
  return {{"pairs", a.pairs},
          {"pairs_matched", a.pairs_matched},
          {"correspondences", a.correspondences},
          {"rounds", a.rounds},
          {"initial_cost", a.initial_cost},
          {"final_cost", a.final_cost}};
}

Json RgbdJson(const RgbdQuality& r) {
  return {{"frames", r.frames},
          {"key_frames", r.key_frames},
          {"alignments", r.alignments},
          {"aligned", r.aligned},
          {"loop_alignments", r.loop_alignments},
          {"loops_found", r.loops_found},
          {"loops_accepted", r.loops_accepted},
          {"loops_rejected", r.loops_rejected}};
}

Json VisualOdometryJson(const ReconstructionQuality& q) {
  Json json;
  json["mode"] = "visual-odometry";
  json["frames"] = q.frames;
  json["frames_tracked"] = q.frames_tracked;
  json["key_frames"] = q.key_frames;
  json["segments"] = q.segments;
  json["run_time_s"] = q.run_time_s;
  json["frames_per_s"] = q.scans_per_s;
  json["warnings"] = q.warnings;
  return json;
}

Json SlamJson(const ReconstructionQuality& q) {
  Json json;
  json["scans"] = q.scans;
  json["scans_tracked"] = q.scans_tracked;
  json["scans_without_echoes"] = q.scans_without_echoes;
  json["ground_echoes_dropped"] = q.ground_echoes_dropped;
  json["scans_moving_echo_filtered"] = q.scans_moving_echo_filtered;
  json["moving_echoes_dropped"] = q.moving_echoes_dropped;
  json["scans_given_up_to_moving_echoes"] = q.scans_given_up_to_moving_echoes;
  json["stamps_backwards"] = q.stamps_backwards;
  json["stamps_duplicate"] = q.stamps_duplicate;
  json["odometry_missing"] = q.odometry_missing;
  json["odometry_rejected"] = q.odometry_rejected;
  json["odometry_arbitrated_by_laser"] = q.odometry_arbitrated_by_laser;
  Json routines = Json::object();
  for (const auto& [name, count] : q.routines) routines[name] = count;
  json["routines"] = routines;
  json["key_frames"] = q.key_frames;
  json["loop_closures_found"] = q.loop_closures_found;
  json["loop_closures_accepted"] = q.loop_closures_accepted;
  json["loop_closures_rejected"] = q.loop_closures_rejected;
  json["loop_closures_rejected_match"] = q.loop_closures_rejected_match;
  json["loop_closures_rejected_disagreement"] = q.loop_closures_rejected_disagreement;
  json["loop_closures_rejected_degenerate"] = q.loop_closures_rejected_degenerate;
  json["loop_closures_rejected_after_optimisation"] = q.loop_closures_rejected_after_optimisation;
  json["loop_closures_rejected_inconsistent"] = q.loop_closures_rejected_inconsistent;
  json["loop_closures_confirmed"] = q.loop_closures_confirmed;
  json["landmarks"] = LandmarksJson(q.landmarks);
  json["optimisations"] = q.optimisations;
  json["final_cost"] = q.final_cost;
  if (q.scan_alignment) json["scan_alignment"] = ScanAlignmentJson(*q.scan_alignment);
  if (q.scan_refinement) json["scan_refinement"] = ScanAlignmentJson(*q.scan_refinement);
  if (q.rgbd) json["rgbd"] = RgbdJson(*q.rgbd);
  json["run_time_s"] = q.run_time_s;
  json["scans_per_s"] = q.scans_per_s;
  json["warnings"] = q.warnings;
  return json;
}

// Reads json[key] into `value` when it is a number; leaves `value` otherwise.
template <typename T>
void Read(const Json& json, const char* key, T& value) {
  const auto it = json.find(key);
  if (it != json.end() && it->is_number()) value = it->get<T>();
}

const Json* Object(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_object() ? &*it : nullptr;
}

void ReadNested(const Json& json, ReconstructionQuality& q) {
  if (const Json* l = Object(json, "landmarks")) {
    Read(*l, "in_graph", q.landmarks.in_graph);
    Read(*l, "sightings", q.landmarks.sightings);
    Read(*l, "associated_by_tracking", q.landmarks.associated_by_tracking);
    Read(*l, "loops_found", q.landmarks.loops_found);
    Read(*l, "loops_accepted", q.landmarks.loops_accepted);
    Read(*l, "loops_rejected", q.landmarks.loops_rejected);
  }
  for (const auto& [key, field] :
       {std::pair{"scan_alignment", &ReconstructionQuality::scan_alignment},
        std::pair{"scan_refinement", &ReconstructionQuality::scan_refinement}}) {
    const Json* a = Object(json, key);
    if (a == nullptr) continue;
    ScanAlignmentQuality& s = (q.*field).emplace();
    Read(*a, "pairs", s.pairs);
    Read(*a, "pairs_matched", s.pairs_matched);
    Read(*a, "correspondences", s.correspondences);
    Read(*a, "rounds", s.rounds);
    Read(*a, "initial_cost", s.initial_cost);
    Read(*a, "final_cost", s.final_cost);
  }
  if (const Json* r = Object(json, "rgbd")) {
    RgbdQuality& s = q.rgbd.emplace();
    Read(*r, "frames", s.frames);
    Read(*r, "key_frames", s.key_frames);
    Read(*r, "alignments", s.alignments);
    Read(*r, "aligned", s.aligned);
    Read(*r, "loop_alignments", s.loop_alignments);
    Read(*r, "loops_found", s.loops_found);
    Read(*r, "loops_accepted", s.loops_accepted);
    Read(*r, "loops_rejected", s.loops_rejected);
  }
  if (const Json* routines = Object(json, "routines")) {
    for (const auto& [name, count] : routines->items()) {
      if (count.is_number()) q.routines.emplace_back(name, count.get<std::size_t>());
    }
  }
  if (const auto list = json.find("warnings"); list != json.end() && list->is_array()) {
    for (const Json& warning : *list) {
      if (warning.is_string()) q.warnings.push_back(warning.get<std::string>());
    }
  }
}

void ReadCounts(const Json& json, ReconstructionQuality& q) {
  Read(json, "scans", q.scans);
  Read(json, "scans_tracked", q.scans_tracked);
  Read(json, "scans_without_echoes", q.scans_without_echoes);
  Read(json, "ground_echoes_dropped", q.ground_echoes_dropped);
  Read(json, "scans_moving_echo_filtered", q.scans_moving_echo_filtered);
  Read(json, "moving_echoes_dropped", q.moving_echoes_dropped);
  Read(json, "scans_given_up_to_moving_echoes", q.scans_given_up_to_moving_echoes);
  Read(json, "stamps_backwards", q.stamps_backwards);
  Read(json, "stamps_duplicate", q.stamps_duplicate);
  Read(json, "odometry_missing", q.odometry_missing);
  Read(json, "odometry_rejected", q.odometry_rejected);
  Read(json, "odometry_arbitrated_by_laser", q.odometry_arbitrated_by_laser);
  Read(json, "loop_closures_found", q.loop_closures_found);
  Read(json, "loop_closures_accepted", q.loop_closures_accepted);
  Read(json, "loop_closures_rejected", q.loop_closures_rejected);
  Read(json, "loop_closures_rejected_match", q.loop_closures_rejected_match);
  Read(json, "loop_closures_rejected_disagreement", q.loop_closures_rejected_disagreement);
  Read(json, "loop_closures_rejected_degenerate", q.loop_closures_rejected_degenerate);
  Read(json, "loop_closures_rejected_after_optimisation",
       q.loop_closures_rejected_after_optimisation);
  Read(json, "loop_closures_rejected_inconsistent", q.loop_closures_rejected_inconsistent);
  Read(json, "loop_closures_confirmed", q.loop_closures_confirmed);
  Read(json, "optimisations", q.optimisations);
  Read(json, "final_cost", q.final_cost);
  Read(json, "frames", q.frames);
  Read(json, "frames_tracked", q.frames_tracked);
  Read(json, "segments", q.segments);
  Read(json, "key_frames", q.key_frames);
  Read(json, "run_time_s", q.run_time_s);
  Read(json, q.visual_odometry ? "frames_per_s" : "scans_per_s", q.scans_per_s);
}

}  // namespace

std::string ToJson(const ReconstructionQuality& quality) {
  const Json json = quality.visual_odometry ? VisualOdometryJson(quality) : SlamJson(quality);
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::optional<ReconstructionQuality> QualityFromJson(std::string_view text) {
  const Json json = Json::parse(text, nullptr, false);
  if (!json.is_object()) return std::nullopt;
  ReconstructionQuality quality;
  const auto mode = json.find("mode");
  quality.visual_odometry = mode != json.end() && *mode == "visual-odometry";
  ReadCounts(json, quality);
  ReadNested(json, quality);
  return quality;
}

void WriteQualityFile(const std::filesystem::path& file, const ReconstructionQuality& quality) {
  WriteFileAtomically(file, ToJson(quality));
}

ReconstructionQuality ReadQualityFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw BadInputError(file.string() + ": cannot read");
  std::optional<ReconstructionQuality> quality = QualityFromJson(text.str());
  if (!quality) {
    throw BadInputError(file.string() + ": not a JSON object (reconstruct writes it; rerun it)");
  }
  return *quality;
}

}  // namespace littermap::run
