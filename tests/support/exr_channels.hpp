#pragma once
// Every channel of an EXR, by name, read through OpenEXR (from a file: its API reads files or its streams).
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"

namespace lp::test {

struct ExrChannels {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> channels;  // row-major, top to bottom
};

inline ExrChannels exr_channels(const std::string& bytes) {
  const TempDir dir;
  const std::string path = (dir.path() / "channels.exr").string();
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  ExrChannels out;
  out.width = window.max.x - window.min.x + 1;
  out.height = window.max.y - window.min.y + 1;
  Imf::FrameBuffer fb;
  for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
    auto& values = out.channels[c.name()];
    values.resize(size_t(out.width) * size_t(out.height));
    fb.insert(c.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                   sizeof(float) * size_t(out.width)));
  }
  file.setFrameBuffer(fb);
  file.readPixels(window.min.y, window.max.y);
  return out;
}

}  // namespace lp::test
