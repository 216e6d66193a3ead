// SPDX-License-Identifier: Apache-2.0
// Constants shared by every scw RTL module (Yosys 0.23 needs scoped names: no import).
`default_nettype none

package scw_pkg;
  // Grey level width on every pixel stream (the thesis scales its 10-bit camera to 8 bits).
  localparam int unsigned PixelBits = 8;
  // A beat packed into one word, as FIFOs carry it and hex vectors store it:
  // {eol, sof, px[P-1], ..., px[0]}.
  localparam int unsigned BeatFlagBits = 2;
  // One disparity on the disparity, road and labelling streams: Q11.4 two's complement, invalid
  // = 0 or negative (hls::disparity::disp_t).
  localparam int unsigned DispBits /*verilator public*/ = 16;
  // The labelling stage's object word, {label_desc_t, is_status} or {label_status_t, is_status}:
  // the widths of its fields, here and nowhere else. The C++ reads these numbers from the header
  // CMake writes from this file (cmake/ScwPkgHeader.cmake; sim/words/labelling_pack.hpp's field
  // table), so a width changed here changes the RTL word, the C++ packing and the vector layouts.
  // An object's pixel count, and a status word's object count in the same place:
  localparam int unsigned AreaBits  /*verilator public*/ = 32;
  // Positions and Q11.4 disparities (x_min .. first_y):
  localparam int unsigned CoordBits /*verilator public*/ = 16;
  // Moments and disparity sums (m10 .. sum_dd):
  localparam int unsigned SumBits   /*verilator public*/ = 64;
  // The words between the stages, as sim/ packs them: the labelling stage's object word (897 bits
  // at the widths above), the warning stage's frame result (sim/words/warning_pack.hpp, 199) and
  // the top's result word, the frame result and both cameras' input flags
  // (sim/words/pipeline_pack.hpp). Verilator exports them (V<prefix>_scw_pkg), and
  // sim/builds/pipeline_small_rtl.hpp checks them against the C++ packs.
  // ObjWordBits is label_desc_t's width plus is_status (Yosys 0.23 cannot take $bits of a type
  // here; scw_labelling checks the two agree at elaboration).
  localparam int unsigned ObjWordBits    /*verilator public*/ =
      1 + AreaBits + 10 * CoordBits + 11 * SumBits;
  // The warning stage's frame result, warning_result_t below: its severity, counts and distance
  // (sim/words/warning_pack.hpp's kResultFields reads these numbers too).
  localparam int unsigned SeverityBits   /*verilator public*/ = 2;
  localparam int unsigned CountBits      /*verilator public*/ = 16;
  localparam int unsigned DistMmBits     /*verilator public*/ = 32;
  // Five flags, three counts, the distance and the deciding object's seven coordinates
  // (scw_warning checks at elaboration that this is warning_result_t's width).
  localparam int unsigned ResultWordBits /*verilator public*/ =
      SeverityBits + 5 + 3 * CountBits + DistMmBits + 7 * CoordBits;
  localparam int unsigned PipeResultBits /*verilator public*/ = ResultWordBits + 2;
  // One labelling object descriptor: the object word of sim/words/labelling_pack.hpp without its
  // is_status bit, declared most significant first (area the lowest bits, sum_dd the highest).
  typedef struct packed {
    logic [SumBits-1:0] sum_dd;
    logic [SumBits-1:0] sum_d;
    logic [SumBits-1:0] m03;
    logic [SumBits-1:0] m12;
    logic [SumBits-1:0] m21;
    logic [SumBits-1:0] m30;
    logic [SumBits-1:0] m02;
    logic [SumBits-1:0] m11;
    logic [SumBits-1:0] m20;
    logic [SumBits-1:0] m01;
    logic [SumBits-1:0] m10;
    logic [CoordBits-1:0] first_y;
    logic [CoordBits-1:0] first_x;
    logic [CoordBits-1:0] closest_y;
    logic [CoordBits-1:0] closest_x;
    logic [CoordBits-1:0] d_max;
    logic [CoordBits-1:0] d_min;
    logic [CoordBits-1:0] y_max;
    logic [CoordBits-1:0] y_min;
    logic [CoordBits-1:0] x_max;
    logic [CoordBits-1:0] x_min;
    logic [AreaBits-1:0] area;
  } label_desc_t;
  // A frame's status word without its is_status bit (the rest of the word zero): the object
  // count where an object's area is, then the flags.
  typedef struct packed {
    logic                stream_error;
    logic                object_overflow;
    logic                tile_overflow;
    logic [AreaBits-1:0] objects;
  } label_status_t;
  // The deciding object's coordinates in a frame result; a status-decided frame has none.
  typedef struct packed {
    logic [CoordBits-1:0] y_max;
    logic [CoordBits-1:0] y_min;
    logic [CoordBits-1:0] x_max;
    logic [CoordBits-1:0] x_min;
    logic [CoordBits-1:0] d_max;
    logic [CoordBits-1:0] closest_y;
    logic [CoordBits-1:0] closest_x;
  } result_box_t;
  // The warning stage's frame result (hls::warning::FrameResult), most significant first:
  // severity the lowest bits, y_max the highest. distance_mm is two's complement.
  typedef struct packed {
    result_box_t           box;
    logic [DistMmBits-1:0] distance_mm;
    logic [CountBits-1:0]  index;
    logic [CountBits-1:0]  obstacles;
    logic [CountBits-1:0]  objects;
    logic                  stream_error;
    logic                  object_overflow;
    logic                  tile_overflow;
    logic                  too_close;
    logic                  in_tunnel;
    logic [SeverityBits-1:0] severity;
  } warning_result_t;
  // The warning stage's configuration (hls::warning::WarningConfig but road_height, a port of
  // its own), one word on the cfg_warning_i port of scw_warning and of the top: the layout here
  // and in sim/words/warning_cfg.hpp's kConfigFields, which packs a WarningConfig into it (the
  // C++ drive, and the vector sets' cfg word). Lengths in mm and Q12.4 pixel values are 16 bits,
  // the baseline Q12.8 mm 20, the spread rule's k Q4.4 8; the vehicle offsets are two's
  // complement.
  localparam int unsigned CfgBaselineBits /*verilator public*/ = 20;
  localparam int unsigned CfgFieldBits    /*verilator public*/ = 16;
  localparam int unsigned CfgSpreadBits   /*verilator public*/ = 8;
  // warning_cfg_t's width (Yosys 0.23 cannot take $bits of a type here; scw_warning checks the
  // two agree at elaboration).
  localparam int unsigned WarningCfgBits  /*verilator public*/ =
      CfgBaselineBits + 13 * CfgFieldBits + 1 + CfgSpreadBits;
  // Most significant first: baseline_q8 the lowest bits, spread_q4 the highest.
  typedef struct packed {
    logic [CfgSpreadBits-1:0]   spread_q4;
    logic                       rule;  // hls::warning::DistanceRule: 0 closest, 1 spread
    logic [CfgFieldBits-1:0]    d_limit_q4;
    logic [CfgFieldBits-1:0]    min_height_mm;
    logic [CfgFieldBits-1:0]    near_mm;
    logic [CfgFieldBits-1:0]    medium_mm;
    logic [CfgFieldBits-1:0]    high_mm;
    logic [CfgFieldBits-1:0]    tunnel_h_mm;
    logic [CfgFieldBits-1:0]    tunnel_half_w_mm;
    logic [CfgFieldBits-1:0]    veh_z_mm;
    logic [CfgFieldBits-1:0]    veh_y_mm;
    logic [CfgFieldBits-1:0]    veh_x_mm;
    logic [CfgFieldBits-1:0]    cv_q4;
    logic [CfgFieldBits-1:0]    cu_q4;
    logic [CfgFieldBits-1:0]    focal_q4;
    logic [CfgBaselineBits-1:0] baseline_q8;
  } warning_cfg_t;
  // The road stage's configuration (hls::road::RoadConfig), one word on the cfg_road_i port of
  // scw_road and of the top: the layout here and in sim/words/road_cfg.hpp's kConfigFields. The
  // slopes are codes x 2^12 a row (hls::road::kSlopeBits), the intercept two's complement, the
  // horizon rows 0 .. 1023, the tolerances Q11.4 and their relative parts Q0.8, the fit's
  // minimum pixel count 20 bits.
  localparam int unsigned RoadSlopeBits     /*verilator public*/ = 18;
  localparam int unsigned RoadInterceptBits /*verilator public*/ = 32;
  localparam int unsigned RoadRowBits       /*verilator public*/ = 10;
  localparam int unsigned RoadTolBits       /*verilator public*/ = 15;
  localparam int unsigned RoadRelBits       /*verilator public*/ = 8;
  localparam int unsigned RoadCountBits     /*verilator public*/ = 20;
  // road_cfg_t's width (scw_road checks the two agree at elaboration).
  localparam int unsigned RoadCfgBits       /*verilator public*/ =
      1 + 3 * RoadSlopeBits + RoadInterceptBits + 2 * RoadRowBits + 2 * RoadTolBits +
      2 * RoadRelBits + RoadCountBits;
  // Most significant first: enable the lowest bit, min_count the highest.
  typedef struct packed {
    logic [RoadCountBits-1:0]     min_count;
    logic [RoadRelBits-1:0]       gate_rel_q8;
    logic [RoadTolBits-1:0]       gate_q4;
    logic [RoadRelBits-1:0]       tol_rel_q8;
    logic [RoadTolBits-1:0]       tol_q4;
    logic [RoadRowBits-1:0]       h_max;
    logic [RoadRowBits-1:0]       h_min;
    logic [RoadSlopeBits-1:0]     a_max;
    logic [RoadSlopeBits-1:0]     a_min;
    logic [RoadInterceptBits-1:0] nominal_b;
    logic [RoadSlopeBits-1:0]     nominal_a;
    logic                         enable;
  } road_cfg_t;
  // The disparity stage's configuration (hls::disparity::DisparityConfig but the frame's width
  // and height, the top's cfg_width_i and cfg_height_i), one word on the cfg_disparity_i port of
  // scw_disparity and of the top: the layout here and in sim/words/disparity_cfg.hpp's
  // kConfigFields. The widths are those of the largest build (MaxWidthPx 2048, NumDisp 128); a
  // build reads the low $clog2(MaxWidthPx + 1) bits of dmin and compares num_disp and
  // edge_candidates whole. The SAD limit and the texture threshold are the C++ int fields, at
  // least 0 (0 is off).
  localparam int unsigned DispDminBits   /*verilator public*/ = 12;
  localparam int unsigned DispNumBits    /*verilator public*/ = 8;
  localparam int unsigned DispCapBits    /*verilator public*/ = 6;
  localparam int unsigned DispLimitBits  /*verilator public*/ = 32;
  localparam int unsigned DispRatioBits  /*verilator public*/ = 8;
  // disparity_cfg_t's width (scw_disparity checks the two agree at elaboration).
  localparam int unsigned DisparityCfgBits /*verilator public*/ =
      DispDminBits + 2 * DispNumBits + DispCapBits + 2 * DispLimitBits + DispRatioBits + 3;
  // Most significant first: dmin the lowest bits, edge_candidates the highest.
  typedef struct packed {
    logic [DispNumBits-1:0]   edge_candidates;
    logic                     opencv_invalid;
    logic                     subpixel;
    logic [DispRatioBits-1:0] uniqueness_ratio;
    logic [DispLimitBits-1:0] texture_threshold;
    logic [DispLimitBits-1:0] sad_limit;
    logic [DispCapBits-1:0]   prefilter_cap;
    logic                     prefilter;
    logic [DispNumBits-1:0]   num_disp;
    logic [DispDminBits-1:0]  dmin;
  } disparity_cfg_t;
  // The labelling stage's configuration (hls::labelling::LabellingConfig but the frame's width
  // and height, the top's cfg_width_i and cfg_height_i), one word on the cfg_labelling_i port of
  // scw_labelling and of the top: the layout here and in sim/words/labelling_cfg.hpp's
  // kConfigFields. The tile sizes saturate at 65535 (such a tile never closes inside a frame),
  // the floor is Q11.4 two's complement, min_area a pixel count.
  localparam int unsigned LabTileBits    /*verilator public*/ = 16;
  localparam int unsigned LabFloorBits   /*verilator public*/ = 16;
  localparam int unsigned LabMinAreaBits /*verilator public*/ = 32;
  // labelling_cfg_t's width (scw_labelling checks the two agree at elaboration).
  localparam int unsigned LabellingCfgBits /*verilator public*/ =
      2 * LabTileBits + LabFloorBits + LabMinAreaBits;
  // Most significant first: tile_w the lowest bits, min_area the highest.
  typedef struct packed {
    logic [LabMinAreaBits-1:0] min_area;
    logic [LabFloorBits-1:0]   floor;
    logic [LabTileBits-1:0]    tile_h;
    logic [LabTileBits-1:0]    tile_w;
  } labelling_cfg_t;
endpackage
