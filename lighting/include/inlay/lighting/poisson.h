// Poisson reconstruction on an image grid with Neumann boundaries: find u with L u = f, where L
// is the 5-point graph Laplacian ((L u)_i = sum over the 4-neighbours j inside the grid of
// u_j - u_i, the adjoint of forward differences), f sums to zero, and u has mean zero.
// Retinex reconstructs log reflectance from its kept gradients with it.
#pragma once

#include <vector>

namespace inlay {

struct PoissonReport {
  int cycles = 0;               // multigrid V-cycles run
  double relativeResidual = 0;  // |f - L u| / |f| (RMS) at the end
};

// Exact solve by a DCT-II (cv::dct). Odd sizes are padded by one zero-divergence row/column,
// which makes it approximate there. Time grows badly when a side has a large prime factor.
std::vector<float> poissonNeumannDct(const std::vector<float>& f, int W, int H);

// Cell-centred multigrid (red-black Gauss-Seidel, bilinear prolongation, coarsest grid by the
// DCT): V-cycles until the relative residual is below `tolerance` or `maxCycles` ran. Linear
// time and memory (about 4 floats per pixel), parallel by rows.
std::vector<float> poissonNeumannMultigrid(const std::vector<float>& f, int W, int H,
                                           double tolerance = 1e-5, int maxCycles = 30,
                                           PoissonReport* report = nullptr);

}  // namespace inlay
