#pragma once
// How close an encoded video is to the frames it was made from: PSNR and SSIM
// of the decoded yuv420p frames against the source frames converted to
// yuv420p the way VideoEncoder converts them (BT.709, limited range), so only
// the encoder's loss is measured.
#include <string>
#include <vector>

#include "render/gl/image.hpp"

namespace robozoo::render {

struct VideoQuality {
  int frames = 0;     ///< frames decoded and compared (count)
  double psnr_y = 0;  ///< PSNR of the luma plane over all frames (dB; infinity when identical)
  double psnr = 0;    ///< PSNR of all three planes, luma weighted 4:1:1 as ffmpeg's psnr filter (dB)
  double ssim_y = 0;  ///< mean SSIM of the luma plane, 8x8 windows every 4 pixels (1: identical)
};

/// Decodes `path` and compares its frame i with `sources[i % sources.size()]`.
/// Throws std::runtime_error when the file cannot be decoded or its size is
/// not the sources'.
VideoQuality measure_quality(const std::string& path, const std::vector<Image>& sources);

}  // namespace robozoo::render
