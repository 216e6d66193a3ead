// SPDX-License-Identifier: Apache-2.0
// The warning overlay of thesis Fig. 5.11 b: the driving tunnel in perspective with distance
// marks, the deciding object's bounding cuboid in its severity colour, and its distance.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "hls/warning/warning_params.hpp"
#include "host/warning/setup.hpp"

namespace scw::host::warning {

/// The object the overlay draws: what a frame result (or the reference) says about the deciding
/// obstacle, in pixels and metres.
struct OverlayObject {
  // Bounding box, inclusive pixels: the object's x_min, y_min, x_max, y_max.
  int u0 = 0, v0 = 0, u1 = 0, v1 = 0;
  double z_m = 0.0;         // depth (camera z) of its front face: from the result's d_max here;
                            // scw run sets the distance rule's depth from the object's evaluation
  double distance_m = 0.0;  // from the bumper; an upper bound when too_close
  hls::warning::Severity severity = hls::warning::Severity::kNone;
  bool too_close = false;  // closer than the disparity search range measures
};

/// Drawing choices. The cuboid's depth is not measured (the frame result carries only d_max), so
/// its back face is the front face pushed back by a fixed depth: 0.5 m, about a pedestrian's or a
/// crossing bike's, where pushing back by the width would make a side-on bike 1.8 m deep.
struct OverlayStyle {
  double tunnel_length_m = 20.0;  // from the bumper, as in Fig. 5.11 b
  double mark_step_m = 5.0;       // cross marks every 5 m up to tunnel_length_m
  double near_clip_m = 0.5;       // only the parts with camera z > this are drawn
  double cuboid_depth_m = 0.5;
  int tunnel_thickness_px = 1;
  int cuboid_thickness_px = 2;
  double font_scale = 0.5;
  cv::Scalar tunnel_bgr{255, 160, 0};  // blue: none of the severity colours
};

/// BGR colour of a severity: green low, yellow medium, red high (white for none).
cv::Scalar severity_bgr(hls::warning::Severity s);

/// The upper-left caption: "6.24 m medium", "< 2.37 m high" when too close, "no obstacle" when
/// `deciding` is null or not an obstacle.
std::string overlay_caption(const OverlayObject* deciding);

/// Pinhole projection of a camera-frame point (m): u = cu + f x / z, v = cv - f y / z.
cv::Point2d project(const Eigen::Vector3d& p, const WarningSetup& s);

/// The deciding object of a frame result, or nullopt when the frame has none. The depth comes
/// from its d_max (eq. 2.18: z = b f / d).
std::optional<OverlayObject> overlay_object(const hls::warning::FrameResult& r,
                                            const WarningSetup& s);

/// The overlay on a copy of the rectified left image (CV_8UC1 or CV_8UC3; the result is CV_8UC3
/// of the same size). `deciding` may be null: the tunnel and "no obstacle" only. Throws
/// std::invalid_argument for an empty image or another pixel type.
cv::Mat draw_overlay(const cv::Mat& rectified_left, const WarningSetup& s,
                     const OverlayObject* deciding, const OverlayStyle& style = {});

}  // namespace scw::host::warning
