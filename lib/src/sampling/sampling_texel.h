// sampling_texel.h (private) - reading single texels of an equirect image with the value
// policies, for the methods of sampling_methods.h that read texels one at a time.
//
// There is one implementation of the policies, the row loader of row_kernel.h
// (load_row_planes): a texel is read as a one-texel row of it, so a grey image feeds
// channel 0 to R, G and B, a NaN or Inf channel is counted (once per texel) and read as 0,
// a finite negative channel is counted and kept or read as 0 (Negative::Clamp), and
// max_value is the largest value after replacement, exactly as in project_equirect.
#pragma once

#include <array>
#include <cstdint>

#include "projection/row_kernel.h"
#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/status.h"

namespace shpack::detail {

class TexelReader {
 public:
  // `image` must be resolved (resolve_view).
  TexelReader(const ImageView& image, const ProjectOptions& options) noexcept
      : image_(image), options_(options) {}

  // Texel (x, y), x < width, y < height, as R, G, B after the policies, counted into
  // counts(). Returns false if the texel is non-finite and the policy is NonFinite::Error
  // (rgb then holds the texel with its non-finite values read as 0).
  bool read(std::uint32_t x, std::uint32_t y, std::array<double, 3>& rgb) noexcept;

  // The texel direction d falls in (equirect_texel), as read(x, y, rgb).
  bool read(const Dir3& d, std::array<double, 3>& rgb) noexcept;

  const ImageView& image() const noexcept { return image_; }
  const TexelCounts& counts() const noexcept { return counts_; }
  // NonFiniteTexel at the first non-finite texel read (valid once read returned false).
  Status nonfinite_error() const noexcept {
    return Status::error(Errc::NonFiniteTexel, "NaN or Inf texel", counts_.first_nonfinite_x,
                         counts_.first_nonfinite_y);
  }

 private:
  ImageView image_;
  ProjectOptions options_;
  TexelCounts counts_;
};

// ProjectStats as project_equirect reports them.
inline ProjectStats stats_from_counts(const TexelCounts& c) noexcept {
  return {c.nonfinite, c.negative, c.first_nonfinite_x, c.first_nonfinite_y, c.max_value};
}

}  // namespace shpack::detail
