// SPDX-License-Identifier: Apache-2.0
#include "host/app/run.hpp"

#include <stdexcept>

#include "host/app/classify.hpp"
#include "host/app/group.hpp"
#include "host/app/track.hpp"
#include "host/ground/run_model.hpp"
#include "host/labelling/hu_moments.hpp"
#include "host/labelling/picture.hpp"
#include "host/reference/ground_ref.hpp"
#include "host/road/setup.hpp"
#include "host/warning/overlay.hpp"
#include "host/warning/run_model.hpp"

namespace scw::app {

struct Runner::AppLayer {
  std::unique_ptr<Classifier> classifier;
  Tracker tracker;
  AppLayer(const RunOptions& o, TrackerParams tp)
      : classifier(o.classifier.empty()
                       ? std::make_unique<ParallelepipedClassifier>(o.classifier_s)
                       : load_classifier(o.classifier)),
        tracker(tp) {}
};

namespace {

TrackerParams tracker_params(const RunOptions& o) {
  TrackerParams p;
  p.use_kalman = o.kalman;
  p.frame_period_s = o.frame_period_s;
  return p;
}

}  // namespace

Runner::Runner(const RunOptions& options, std::optional<RectifyMaps> maps, StageEngine engine)
    : opt_(options), maps_(std::move(maps)), engine_(std::move(engine)), app_(std::make_unique<AppLayer>(options, tracker_params(options))) {
  opt_.warning.d_limit_px = opt_.max_disp;
  host::warning::to_fixed(opt_.warning);  // fail early, naming the value
  if (maps_ && !engine_) {
    rect_left_ = std::make_unique<rectify::Rectifier>(maps_->left, maps_->lead_rows);
    rect_right_ = std::make_unique<rectify::Rectifier>(maps_->right, maps_->lead_rows);
  }
}

Runner::~Runner() = default;

namespace {

/// The label whose object is the stage's `index`-th word (objects are unique by first pixel).
int label_of(const labelling::Segmentation& seg, std::size_t index) {
  if (index >= seg.objects.size()) return 0;
  const auto& o = seg.objects[index];
  for (std::size_t k = 0; k < seg.objects_by_label.size(); ++k)
    if (seg.objects_by_label[k].first_x == o.first_x && seg.objects_by_label[k].first_y == o.first_y)
      return static_cast<int>(k) + 1;
  return 0;
}

}  // namespace

void Runner::classify_and_track(FrameOutput& out, const hls::warning::WarningConfig& wcfg,
                                const hls::road::Line& road) {
  std::vector<hls::labelling::Object> objects;
  std::vector<hls::warning::ObjectEval> evals;
  for (const auto& r : out.objects) {
    objects.push_back(r.object);
    evals.push_back(r.eval);
  }
  std::vector<Detection> detections;
  for (const Target& t : group_objects(objects, evals)) {
    TargetReport tr;
    for (int k : t.parts) {
      tr.labels.push_back(k + 1);
      out.objects[static_cast<std::size_t>(k)].target = static_cast<int>(out.targets.size());
    }
    tr.object = t.object;
    tr.eval = warning::evaluate_object(t.object, wcfg, &road);
    const auto hu = labelling::hu_moments(t.object);
    tr.hu = {hu[0], hu[1], hu[2]};
    Features f;
    f.hu1 = hu[0];
    f.hu2 = hu[1];
    f.hu3 = hu[2];
    f.width_m = tr.eval.width_mm / 1000.0;
    f.height_m = tr.eval.height_mm / 1000.0;
    const ObjectClass c = app_->classifier->classify(f);
    tr.cls = to_string(c);
    if (c != ObjectClass::kOther) {
      // The bounding cuboid's centre in vehicle coordinates (its front face at the closest
      // point's depth, as deep as it is wide).
      const auto& e = tr.eval;
      const double vx = 0.5 * (e.x0_mm + e.x1_mm) - wcfg.veh_x_mm;
      const double vy = 0.5 * (e.y_top_mm + e.y_bot_mm) - wcfg.veh_y_mm;
      const double vz = e.z_mm - wcfg.veh_z_mm + 0.5 * e.width_mm;
      Detection d;
      d.cls = static_cast<int>(c);
      d.hu = tr.hu;
      d.width_m = f.width_m;
      d.height_m = f.height_m;
      d.centre_m = Eigen::Vector3d(vx, vy, vz) / 1000.0;
      d.source_index = static_cast<int>(out.targets.size());
      detections.push_back(d);
    }
    out.targets.push_back(tr);
  }
  for (const TrackUpdate& u : app_->tracker.update(detections)) {
    TargetReport& tr = out.targets[static_cast<std::size_t>(u.source_index)];
    tr.track = u.track_id;
    if (const Track* t = app_->tracker.find(u.track_id); t && t->has_speed) {
      tr.has_speed = true;
      tr.velocity_mps = {t->velocity.x(), t->velocity.y(), t->velocity.z()};
    }
  }
  for (auto& r : out.objects) {
    if (r.target < 0) continue;
    r.cls = out.targets[static_cast<std::size_t>(r.target)].cls;
    r.track = out.targets[static_cast<std::size_t>(r.target)].track;
  }
}

FrameOutput Runner::process(const cv::Mat& left_grey, const cv::Mat& right_grey) {
  if (left_grey.size() != right_grey.size())
    throw std::invalid_argument("left and right images differ in size (" +
                                std::to_string(left_grey.cols) + " x " +
                                std::to_string(left_grey.rows) + " vs " +
                                std::to_string(right_grey.cols) + " x " +
                                std::to_string(right_grey.rows) + ")");
  FrameOutput out;
  StageOutputs hw;
  hls::road::Line road;  // the frame's road: the warning stage measures heights above it
  if (engine_) {
    hw = engine_(left_grey, right_grey);
    out.left = hw.left;
    out.right = hw.right;
    out.disparity = hw.disparity;
    out.road_mask = hw.road_mask;
    road = hw.road;
  } else if (maps_) {
    out.left = (*rect_left_)(left_grey);
    out.right = (*rect_right_)(right_grey);
  } else {
    out.left = left_grey;
    out.right = right_grey;
  }
  if (!engine_) {
    auto dcfg = disparity::mode_config(opt_.mode, out.left.cols, out.left.rows, opt_.min_disp);
    dcfg.edge_candidates = opt_.edge_candidates;
    out.disparity = disparity::disparity_image(out.left, out.right, opt_.window, opt_.min_disp,
                                               opt_.max_disp, dcfg);
    // The road stage always fits the road (heights are measured above it); it removes it from
    // the labelling's input only with opt_.road, as in the pipeline.
    if (!road_) {
      const double cv = opt_.warning.cv_px != 0.0 ? opt_.warning.cv_px
                                                  : 0.5 * (out.disparity.rows - 1);
      auto rs = road::rig_setup(opt_.warning.baseline_m, opt_.warning.focal_px, cv,
                                opt_.camera_height_m, opt_.camera_pitch_deg);
      rs.enable = opt_.road;
      road_ = std::make_unique<road::RoadFilter>(road::to_fixed(rs));
    }
    const cv::Mat before = out.disparity;
    out.disparity = road_->filter(before);
    out.road_mask = road::removed_mask(before, out.disparity);
    road = road_->road();
    if (opt_.ground)
      out.disparity = ground::remove_ground(
          out.disparity,
          ground::default_ground_config(opt_.warning.baseline_m, opt_.camera_height_m));
  }
  if (out.road_mask.empty()) out.road_mask = cv::Mat::zeros(out.disparity.size(), CV_8U);
  cv::Mat q4;
  out.disparity.convertTo(q4, CV_16UC1);  // negative (invalid) codes saturate to 0
  const int invalid = static_cast<std::int16_t>(hls::disparity::invalid_code(
      disparity::mode_config(opt_.mode, q4.cols, q4.rows, opt_.min_disp)));
  const auto lcfg = labelling::grid_config(q4.cols, q4.rows, opt_.tiles_x, opt_.tiles_y,
                                           invalid > 0 ? invalid : 0, opt_.min_area);
  // With another engine the host's model labels that engine's map again: the label picture
  // needs each pixel's node, which only the model keeps; the objects must be the engine's.
  out.segmentation = labelling::segment(q4, lcfg);
  const auto& seg = out.segmentation;

  auto wsetup = opt_.warning;
  const auto wcfg = host::warning::to_fixed(wsetup);
  out.result =
      warning::run_warning(warning::table_words(seg.objects, seg.status), wcfg, nullptr, &road);
  if (engine_) {
    if (hw.objects != seg.objects || !(hw.status == seg.status))
      throw std::logic_error("the engine's object table differs from the C++ labelling model's "
                             "on the engine's own disparity map");
    if (hw.result != out.result)
      throw std::logic_error("the engine's frame result differs from the C++ warning model's");
    out.input_error = hw.input_error;
  }
  out.deciding_label =
      out.result.index == 0xffff ? 0 : label_of(seg, out.result.index);

  for (std::size_t k = 0; k < seg.objects_by_label.size(); ++k) {
    ObjectReport r;
    r.label = static_cast<int>(k) + 1;
    r.object = seg.objects_by_label[k];
    r.eval = warning::evaluate_object(r.object, wcfg, &road);
    r.hu = labelling::hu_moments(r.object);
    out.objects.push_back(r);
  }
  classify_and_track(out, wcfg, road);
  auto deciding = host::warning::overlay_object(out.result, wsetup);
  if (deciding && out.deciding_label > 0) {
    const ObjectReport& dec = out.objects[static_cast<std::size_t>(out.deciding_label - 1)];
    // The cuboid's front face at the depth the stage placed the object (its distance rule's).
    deciding->z_m = dec.eval.z_mm / 1000.0;
    // The cuboid bounds the whole target the deciding part belongs to.
    const int t = dec.target;
    if (t >= 0) {
      const auto& o = out.targets[static_cast<std::size_t>(t)].object;
      deciding->u0 = o.x_min;
      deciding->v0 = o.y_min;
      deciding->u1 = o.x_max;
      deciding->v1 = o.y_max;
    }
  }
  const cv::Mat base =
      opt_.overlay_on_labels ? labelling::colour_labels(out.segmentation.labels) : out.left;
  out.overlay = host::warning::draw_overlay(base, wsetup, deciding ? &*deciding : nullptr);
  return out;
}

nlohmann::json result_json(const hls::warning::FrameResult& r) {
  nlohmann::json j;
  j["severity"] = severity_name(r.severity);
  const bool any = r.index != 0xffff;
  j["distance_m"] = any ? nlohmann::json(r.distance_mm / 1000.0) : nlohmann::json(nullptr);
  j["closest_uv"] = any ? nlohmann::json::array({r.closest_x, r.closest_y}) : nlohmann::json(nullptr);
  j["disparity"] = any ? nlohmann::json(r.d_max / 16.0) : nlohmann::json(nullptr);
  j["bbox"] = any ? nlohmann::json::array({r.x_min, r.y_min, r.x_max, r.y_max})
                  : nlohmann::json(nullptr);
  j["in_tunnel"] = r.in_tunnel;
  j["objects"] = r.objects;
  j["obstacles"] = r.obstacles;
  nlohmann::json flags = nlohmann::json::array();
  if (r.too_close) flags.push_back("too_close");
  if (r.tile_overflow) flags.push_back("tile_overflow");
  if (r.object_overflow) flags.push_back("object_overflow");
  if (r.stream_error) flags.push_back("stream_error");
  j["flags"] = flags;
  return j;
}

nlohmann::json frame_json(int frame, const FrameOutput& out) {
  nlohmann::json j = {{"frame", frame}};
  j.update(result_json(out.result));
  if (out.input_error) j["flags"].push_back("input_error");
  j["label"] = out.deciding_label;
  if (out.deciding_label > 0) {
    const auto& o = out.objects[static_cast<std::size_t>(out.deciding_label - 1)];
    j["class"] = o.cls;
    j["track"] = o.track;
    if (o.target >= 0) {
      const auto& t = out.targets[static_cast<std::size_t>(o.target)];
      j["target_bbox"] = {t.object.x_min, t.object.y_min, t.object.x_max, t.object.y_max};
      j["target_labels"] = t.labels;
      j["width_m"] = t.eval.width_mm / 1000.0;
      j["height_m"] = t.eval.height_mm / 1000.0;
      if (t.has_speed) j["velocity_mps"] = t.velocity_mps;
    }
  }
  j["tracks"] = nlohmann::json::array();
  for (const auto& t : out.targets)
    if (t.track >= 0) j["tracks"].push_back({{"track", t.track}, {"class", t.cls},
                                              {"distance_m", t.eval.distance_mm / 1000.0}});
  return j;
}

}  // namespace scw::app
