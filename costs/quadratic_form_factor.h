// The square-root factor of a 2×2 orthotropic energy form, shared by the finite-volume costs.
#ifndef DRAPE_COSTS_QUADRATIC_FORM_FACTOR_H_
#define DRAPE_COSTS_QUADRATIC_FORM_FACTOR_H_

#include <algorithm>
#include <cmath>

namespace drape {

// Upper Cholesky factor of area · [a b; b c], so that
//   ½ area (a x² + 2 b x y + c y²) = ½ ((l11 x + l12 y)² + (l22 y)²),
// which writes the form as residuals (EnergyForm::kSquares). Needs a, c ≥ 0 and b² ≤ a c; with
// a = 0 only the c term remains, and a remainder c − b²/a that rounding leaves just below zero is
// taken as zero.
struct QuadraticFormFactor {
  QuadraticFormFactor(double a, double b, double c, double area)
      : l11(a > 0.0 ? std::sqrt(a * area) : 0.0),
        l12(a > 0.0 ? b / std::sqrt(a) * std::sqrt(area) : 0.0),
        l22(std::sqrt(std::max(0.0, a > 0.0 ? c - b * b / a : c) * area)) {}

  const double l11, l12, l22;
};

}  // namespace drape

#endif  // DRAPE_COSTS_QUADRATIC_FORM_FACTOR_H_
