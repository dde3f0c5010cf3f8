#include "study/thresholds.h"

namespace fp::study {

const char* const kSsimRationale =
    "By SSIM an image counts as not noisy at SSIM >= 0.98, a dissimilarity 1 - SSIM of at most 0.02. Wang "
    "et al. 2004 define the index and show that it orders distorted images as observers do, but give no "
    "value at which a distortion becomes invisible; 0.98 is our assumption. On the Cornell box raw NEE "
    "reaches it at about the sample count at which it reaches relMSE <= 4e-4 (SSIM 0.966 at 128 spp and "
    "0.983 at 256 in the report of docs/study, relMSE crossing at 191), so it restates that demand on the "
    "display image's structure rather than adding an independent one. Change it with --ssim-threshold.";

const char* const kFlipRationale =
    "By FLIP an image counts as not noisy when its mean HDR-FLIP against the reference is at most 0.05, at "
    "67 pixels per degree: an observer 0.7 m from a 0.7 m wide display of 3840 columns, the standard "
    "viewing condition of the FLIP papers (Andersson et al. 2020, \"FLIP: A Difference Evaluator for "
    "Alternating Images\", HPG; Andersson et al. 2021, \"Visualizing Errors in Rendered High Dynamic "
    "Range Images\", Eurographics short papers). What is measured: FLIP's per-pixel value approximates the "
    "difference an observer sees when flipping between the two images at that viewing condition, 0 for "
    "none and 1 for the largest (pure green against pure blue); its colour term spreads the small, common "
    "differences linearly over [0, 0.95] (pc = 0.4, pt = 0.95), and the 2020 paper reports a user study in "
    "which its maps agreed with where observers saw differences better, on average, than the other "
    "metrics it tried. HDR-FLIP takes, per pixel, the largest LDR-FLIP over the exposures the reference "
    "calls for, so it judges dark and bright regions each at an exposure that shows them. What is "
    "assumed: neither paper nor the NVIDIA flip repository's documentation (as far as we read them) gives "
    "a value of the mean below which an image looks converged; the mean is a pooling of the map the tool "
    "reports beside its weighted median and quartiles, not a calibrated visibility threshold. 0.05 is "
    "our choice: on the Cornell box raw NEE reaches it at about the sample count at which it reaches "
    "relMSE <= 4e-4 (mean FLIP 0.053 at 128 spp and 0.042 at 256 in the report of docs/study, relMSE "
    "crossing at 191), and it lies inside 0.01-0.1, the range FLIP-based image regression tests start "
    "from (wgpu's test harness, for one: practice, not evidence). Fine-grained noise keeps mean FLIP "
    "high even where each pixel's error is small: it fell only as about N^-0.4 for raw NEE there, so "
    "FLIP's answer moves most with its threshold, as the band shows. Change it with --flip-threshold.";

}  // namespace fp::study
