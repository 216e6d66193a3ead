// SPDX-License-Identifier: Apache-2.0
// write_objects_csv() and write_frame() (host/app/frame_files.hpp).
#include "host/app/frame_files.hpp"

#include <fstream>
#include <stdexcept>

#include "host/io/image_file.hpp"
#include "host/labelling/picture.hpp"
#include "host/road/run_model.hpp"

namespace scw::app {

namespace fs = std::filesystem;
using host::io::write_image;

void write_objects_csv(const fs::path& p, const FrameOutput& f) {
  std::ofstream csv(p);
  // disparity: what placed the object (the distance rule's); d_max: its largest; height_m: its
  // box's at that depth; above_road_m: its top's above the road where it stands.
  csv << "label,area,u0,v0,u1,v1,closest_u,closest_v,disparity,d_max,x_m,y_m,z_m,width_m,height_m,"
         "distance_m,gap_m,in_tunnel,obstacle,too_close,severity,hu1,hu2,hu3,class,track,"
         "deciding,above_road_m\n";
  for (const auto& r : f.objects) {
    const auto& o = r.object;
    const auto& e = r.eval;
    csv << r.label << ',' << o.area << ',' << o.x_min << ',' << o.y_min << ',' << o.x_max << ','
        << o.y_max << ',' << o.closest_x << ',' << o.closest_y << ',' << e.d_q4 / 16.0 << ','
        << o.d_max / 16.0 << ',' << e.x_mm / 1000.0 << ',' << e.y_mm / 1000.0 << ','
        << e.z_mm / 1000.0 << ',' << e.width_mm / 1000.0 << ',' << e.height_mm / 1000.0 << ','
        << e.distance_mm / 1000.0 << ',' << e.gap_mm / 1000.0 << ',' << e.in_tunnel << ','
        << e.obstacle << ',' << e.too_close << ',' << severity_name(e.severity) << ','
        << r.hu[0] << ',' << r.hu[1] << ',' << r.hu[2] << ',' << r.cls << ',' << r.track << ','
        << (r.label == f.deciding_label) << ',' << e.above_road_mm / 1000.0 << "\n";
  }
  if (!csv) throw std::runtime_error("cannot write '" + p.string() + "'");
}

const char* pictures_name(Pictures p) {
  switch (p) {
    case Pictures::kNone:
      return "none";
    case Pictures::kOverlay:
      return "overlay";
    case Pictures::kAll:
      break;
  }
  return "all";
}

Pictures pictures_from_name(const std::string& name) {
  for (const Pictures p : {Pictures::kNone, Pictures::kOverlay, Pictures::kAll})
    if (name == pictures_name(p)) return p;
  throw std::invalid_argument("pictures '" + name + "': give none, overlay or all");
}

// Kept beside write_frame(), which writes these in this order (tests/app/run.cmake checks a
// run's folder against the list `scw run` prints).
std::string frame_file_names(Pictures pictures) {
  std::string names = "objects.csv";
  if (pictures == Pictures::kNone) return names;
  names += ", overlay.png";
  if (pictures == Pictures::kOverlay) return names;
  return names +
         ", left_rect.png, right_rect.png, disparity16.png, disparity.png, labels.png, "
         "labels_color.png, road.png";
}

void write_frame(const fs::path& dir, const std::string& prefix, const FrameOutput& f,
                 Pictures pictures) {
  write_objects_csv(dir / (prefix + "objects.csv"), f);
  if (pictures == Pictures::kNone) return;
  write_image(dir / (prefix + "overlay.png"), f.overlay);
  if (pictures == Pictures::kOverlay) return;
  write_image(dir / (prefix + "left_rect.png"), f.left);
  write_image(dir / (prefix + "right_rect.png"), f.right);
  // PNG has no signed 16-bit format (imwrite would write 8 bits): the Q11.4 codes go out as
  // CV_16U, invalid (negative) codes saturated to 0.
  cv::Mat q4;
  f.disparity.convertTo(q4, CV_16UC1);
  write_image(dir / (prefix + "disparity16.png"), q4);
  write_image(dir / (prefix + "disparity.png"), labelling::disparity_picture(q4));
  write_image(dir / (prefix + "labels.png"), f.segmentation.labels);
  write_image(dir / (prefix + "labels_color.png"), labelling::colour_labels(f.segmentation.labels));
  write_image(dir / (prefix + "road.png"), road::road_picture(f.left, f.road_mask));
}

}  // namespace scw::app
