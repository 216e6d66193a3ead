// SPDX-License-Identifier: Apache-2.0
// Numbers as text for tables, reports and chart labels, printf-style: written once for the host
// library, the CLI and the benches.
#pragma once

#include <cstdio>
#include <string>

namespace scw::host::io {

/// One number printf-style ("%.3f", "%+.2f", "%.1f %%"): a table's or a label's cell.
inline std::string format_number(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

/// `v` with `decimals` digits after the point ("%.*f").
inline std::string fixed(double v, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

}  // namespace scw::host::io
