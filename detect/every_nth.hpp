#pragma once
// Thins a stream of candidates to every step-th: the first, the (step + 1)-th, and so on, as
// `seen++ % step == 0` would, without a division per candidate (a frame has 300,000 of them).

#include <cstddef>

namespace littermap::detect {

class EveryNth {
 public:
  explicit EveryNth(std::size_t step) : step_(step < 1 ? 1 : step) {}
  // Whether the next candidate is taken.
  bool Take() {
    if (left_ == 0) {
      left_ = step_ - 1;
      return true;
    }
    --left_;
    return false;
  }

 private:
  std::size_t step_;
  std::size_t left_ = 0;
};

}  // namespace littermap::detect
