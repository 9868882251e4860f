#include "engine/image/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lp {

SheetLayout contact_sheet_layout(int frames) {
  if (frames < 1) throw Error(ErrorKind::InvalidArgument, "a contact sheet needs at least one frame");
  int columns = int(std::ceil(std::sqrt(double(frames))));
  return {columns, (frames + columns - 1) / columns};
}

std::vector<uint8_t> contact_sheet(std::span<const Pixels8> frames, SheetLayout layout) {
  if (frames.empty() || int64_t(frames.size()) > int64_t(layout.columns) * layout.rows)
    throw Error(ErrorKind::InvalidArgument, "contact sheet: the frames do not fit its grid");
  const Pixels8& first = frames.front();
  const size_t row_bytes = size_t(first.width) * size_t(first.channels);
  const size_t sheet_row_bytes = row_bytes * size_t(layout.columns);
  std::vector<uint8_t> sheet(sheet_row_bytes * size_t(first.height) * size_t(layout.rows), 0);
  for (size_t i = 0; i < frames.size(); ++i) {
    const Pixels8& f = frames[i];
    check_pixels8(f, "contact sheet");
    if (f.width != first.width || f.height != first.height || f.channels != first.channels)
      throw Error(ErrorKind::InvalidArgument, "the frames of a contact sheet must share their size");
    const size_t column = i % size_t(layout.columns), row = i / size_t(layout.columns);
    uint8_t* cell = sheet.data() + row * size_t(f.height) * sheet_row_bytes + column * row_bytes;
    for (int y = 0; y < f.height; ++y)
      std::memcpy(cell + size_t(y) * sheet_row_bytes, f.bytes.data() + size_t(y) * row_bytes, row_bytes);
  }
  return sheet;
}

}  // namespace lp
