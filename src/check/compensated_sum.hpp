// Neumaier's compensated summation: the sum of many doubles with an error
// bound independent of their number (about one rounding of the result, plus
// the rounding of each term), for volumes summed over millions of elements.
#pragma once

#include <cmath>

namespace partet {

class CompensatedSum {
 public:
  void add(double x) {
    double t = sum_ + x;
    if (std::fabs(sum_) >= std::fabs(x))
      carry_ += (sum_ - t) + x;
    else
      carry_ += (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + carry_; }

 private:
  double sum_ = 0;
  double carry_ = 0;
};

}  // namespace partet
