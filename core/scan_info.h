#pragma once
// `eikon info scan.nrrd|scan_XxYxZ_type.raw`: what a scanned volume holds, so that a user can
// choose its window and its materials' transfer functions: the layout, the extent, the range of
// values, their percentiles and a histogram.
#include <string>

#include "core/scan_volume.h"

namespace eikon {

// The report, several lines, each printable (the path and the header's fields are checked when
// read). `scan` is the file read with no window.
std::string formatScanInfo(const std::string& path, const ScanFile& scan);

// Whether `eikon info` should read `path` as a scan: an NRRD file by content, or a file whose name
// ends in .raw.
bool isScanFile(const std::string& path);

}  // namespace eikon
