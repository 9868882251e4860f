#include "engine/mediancut/summed_area_table.hpp"

#include <algorithm>
#include <new>

#include <sys/mman.h>
#include <tbb/parallel_for.h>

#include "engine/core/error.hpp"

namespace lp {
namespace {

// Rows of the table per strip: enough strips for load balance, few enough offset rows to be cheap.
int strip_rows(int height) { return std::max(16, (height + 63) / 64); }
int strip_count(int height) { return (height + strip_rows(height) - 1) / strip_rows(height); }

// The table's buffer, left uninitialised (every entry is written once by the build). Large tables are
// aligned to and marked for 2 MB pages where the kernel offers them: faulting in 268 MB of 4 KB pages
// took about as long as computing the table.
double* allocate_table(size_t count) {
  constexpr size_t kHuge = size_t{2} << 20;
  const bool huge = count * sizeof(double) >= 4 * kHuge;
  const size_t align = huge ? kHuge : 64;
  const size_t bytes = (count * sizeof(double) + align - 1) / align * align;
  void* p = std::aligned_alloc(align, bytes);
  if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  if (huge) madvise(p, bytes, MADV_HUGEPAGE);  // a hint: without it the table still works, only slower
#endif
  return static_cast<double*>(p);
}

// In place: row[x] = sum of row[0..x] (+ above[x] if given). A plain running sum is one chain of
// dependent additions (one add latency per element); summing each group of four off the chain first
// leaves one dependent add per four elements.
template <bool kAbove>
void accumulate_row(double* row, const double* above, int width) {
  double run = 0.0;
  int x = 0;
  for (; x + 4 <= width; x += 4) {
    const double a0 = row[x], s01 = a0 + row[x + 1], s012 = s01 + row[x + 2], s0123 = s012 + row[x + 3];
    row[x] = run + a0, row[x + 1] = run + s01, row[x + 2] = run + s012, row[x + 3] = run += s0123;
    if constexpr (kAbove)
      for (int i = 0; i < 4; ++i) row[x + i] += above[x + i];
  }
  for (; x < width; ++x) {
    row[x] = run += row[x];
    if constexpr (kAbove) row[x] += above[x];
  }
}

}  // namespace

SummedAreaTable::SummedAreaTable(int width, int height, const RowFill& fill_row)
    : width_(width), height_(height), stride_(size_t(width) + 1) {
  if (width <= 0 || height <= 0) throw Error(ErrorKind::InvalidArgument, "summed-area table needs a non-empty grid");
  table_.reset(allocate_table(size_t(height + 1) * stride_));
  std::fill_n(table_.get(), stride_, 0.0);

  // Table row t (1..height) holds image row t - 1; strip s holds table rows [1 + s*R, 1 + (s+1)*R).
  const int rows_per_strip = strip_rows(height);
  const int strips = strip_count(height);
  tbb::parallel_for(0, strips, [&](int s) {
    const int first = 1 + s * rows_per_strip, last = std::min(height, first + rows_per_strip - 1);
    for (int t = first; t <= last; ++t) {
      double* row = &table_[size_t(t) * stride_];
      row[0] = 0.0;
      fill_row(t - 1, row + 1);
      if (t == first) accumulate_row<false>(row + 1, nullptr, width);
      else accumulate_row<true>(row + 1, row + 1 - stride_, width);
    }
  });

  // Offset of strip s: the full table's row just above it, i.e. the sum of the bottom rows of
  // strips 0 .. s-1 (strip 0 and table row 0 have none).
  offsets_.assign(size_t(strips) * stride_, 0.0);
  for (int s = 1; s < strips; ++s) {
    const double* prev = &offsets_[size_t(s - 1) * stride_];
    const double* bottom = &table_[size_t(s * rows_per_strip) * stride_];
    double* out = &offsets_[size_t(s) * stride_];
    for (size_t x = 0; x < stride_; ++x) out[x] = prev[x] + bottom[x];
  }
  row_offset_.resize(size_t(height) + 1);
  row_offset_[0] = offsets_.data();
  for (int t = 1; t <= height; ++t) row_offset_[t] = &offsets_[size_t((t - 1) / rows_per_strip) * stride_];
}

int64_t SummedAreaTable::memory_bytes(int64_t width, int64_t height) {
  const int64_t rows = height + 1 + strip_count(int(height));
  return rows * (width + 1) * int64_t(sizeof(double)) + (height + 1) * int64_t(sizeof(const double*));
}

}  // namespace lp
