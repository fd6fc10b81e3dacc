#pragma once
// Transfer curves between snell's linear colours and 8/16-bit files. POV-Ray 3.7's default File_Gamma is
// sRGB (DEFAULT_FILE_GAMMA_TYPE kPOVList_GammaType_SRGB in its platform configs), applied after undoing the
// scene's assumed_gamma: a value v leaves as srgb_encode(v^assumed_gamma).
namespace snell::io {

/// IEC 61966-2-1 sRGB encoding of a linear value in [0,1].
double srgb_encode(double linear);
/// The inverse of srgb_encode.
double srgb_decode(double encoded);

/// How linear pixel values become file values.
struct Encoding {
  /// The scene's effective assumed_gamma (Scene::effective_assumed_gamma()).
  double assumed_gamma = 1.0;
  /// True for scenes without gamma handling (pre-3.7 without assumed_gamma): values are written as they are.
  bool passthrough = false;

  /// File value in [0,1] of a pixel value.
  double encode(double value) const;
};

}  // namespace snell::io
