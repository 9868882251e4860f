#pragma once
// The azimuthal sums an SH projection needs from each row of a lat-long map: for every harmonic of phi
// (1, cos phi, sin phi, cos 2 phi, sin 2 phi, ...) the sum over the row's pixels of radiance times the
// harmonic at the pixel's centre, per channel. This is the projection's inner loop (every pixel meets
// every harmonic), written for two pixels at a time in double precision.
#include <array>
#include <vector>

namespace lp {

class RowHarmonics {
 public:
  // The harmonics of m = 0 .. bands - 1 over `width` columns: 2 bands - 1 of them.
  RowHarmonics(int width, int bands);

  int count() const { return harmonics_; }
  // Harmonic h: 0 is 1; 2m - 1 is cos(m phi); 2m is sin(m phi).
  static int cos_index(int m) { return m == 0 ? 0 : 2 * m - 1; }
  static int sin_index(int m) { return 2 * m; }

  // The sums for one row of `width` RGB float pixels, [harmonic][channel].
  std::vector<std::array<double, 3>> sums(const float* rgb_row) const;

 private:
  using Pair = double __attribute__((vector_size(16)));  // two columns side by side
  int width_;
  int harmonics_;
  std::vector<std::vector<Pair>> values_;  // [harmonic][column pair], the last pair zero-padded
};

}  // namespace lp
