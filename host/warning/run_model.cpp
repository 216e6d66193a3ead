// SPDX-License-Identifier: Apache-2.0
#include "host/warning/run_model.hpp"

#include <stdexcept>

#include "hls/warning/warning.hpp"

namespace scw::warning {

std::vector<hls::labelling::LabelPacket> table_words(
    const std::vector<hls::labelling::Object>& objects, const hls::labelling::FrameStatus& status) {
  std::vector<hls::labelling::LabelPacket> words;
  words.reserve(objects.size() + 1);
  for (const auto& o : objects) {
    hls::labelling::LabelPacket p;
    p.data.object = o;
    words.push_back(p);
  }
  hls::labelling::LabelPacket s;
  s.data.is_status = true;
  s.data.status = status;
  s.last = true;
  words.push_back(s);
  return words;
}

namespace {

WarningConfig with_road(WarningConfig cfg, const hls::warning::RoadLine* road) {
  cfg.road_height = road != nullptr;
  return cfg;
}

}  // namespace

FrameResult run_warning(const std::vector<hls::labelling::LabelPacket>& words,
                        const WarningConfig& cfg, std::int64_t* cycles,
                        const hls::warning::RoadLine* road) {
  hls::warning::Warning<HostParams> k(with_road(cfg, road));
  const hls::warning::RoadLine line = road != nullptr ? *road : hls::warning::RoadLine{};
  std::size_t next = 0;
  // Every word is offered on its own clock; the result leaves kLatency clocks after the
  // closing word, so this bound is never reached by a frame that closes.
  const std::int64_t limit = static_cast<std::int64_t>(words.size()) + hls::warning::kLatency + 2;
  for (std::int64_t t = 0; t < limit; ++t) {
    if (k.out_valid()) {
      if (cycles) *cycles = t;
      return k.out().data;
    }
    const bool valid = next < words.size();
    const hls::labelling::LabelPacket in = valid ? words[next] : hls::labelling::LabelPacket{};
    if (valid && k.in_ready(true, true)) ++next;
    k.clock(valid, in, true, true, line);
  }
  throw std::logic_error("run_warning: the words close no frame (no status word or `last`)");
}

hls::warning::ObjectEval evaluate_object(const hls::labelling::Object& o, const WarningConfig& cfg,
                                         const hls::warning::RoadLine* road) {
  return hls::warning::evaluate<HostParams>(o, with_road(cfg, road),
                                            road != nullptr ? *road : hls::warning::RoadLine{});
}

}  // namespace scw::warning
