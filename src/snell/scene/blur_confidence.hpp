#pragma once
// POV-Ray's adaptive focal blur (reference "Focal Blur", confidence and variance): a pixel stops taking
// samples once the variance of its mean colour is small enough that, with the given confidence, more
// samples would not change it by more than `variance`. The thresholds scale a chi-square quantile with the
// sample count, and samples come in batches (7 first, then 6, ... for large counts).
#include <vector>

namespace snell::scene {

/// x such that a chi-square variable with `dof` degrees of freedom exceeds x with probability `tail`.
double chi_square_upper_quantile(double dof, double tail);

/// Threshold on the variance of the mean after n samples, for n = 1..max_samples (index n - 1).
std::vector<double> blur_variance_thresholds(int max_samples, double confidence, double variance);

/// Size of sampling batch `batch` (0, 1, ...) between confidence tests, for a pixel of max_samples.
int blur_batch_size(int batch, int max_samples);

}  // namespace snell::scene
