#include "engine/denoise/unet.hpp"

#include <map>
#include <mutex>
#include <oneapi/dnnl/dnnl.hpp>

#include "engine/denoise/denoiser.hpp"

namespace lp::denoise {
namespace {

using dnnl::memory;
using Dims = memory::dims;

// Encoder then decoder, in execution order; a name in kConcatLayers reads the upsampled tensor and a skip.
const char* const kLayerNames[] = {"enc_conv0",  "enc_conv1",  "enc_conv2",  "enc_conv3",
                                   "enc_conv4",  "enc_conv5a", "enc_conv5b", "dec_conv4a",
                                   "dec_conv4b", "dec_conv3a", "dec_conv3b", "dec_conv2a",
                                   "dec_conv2b", "dec_conv1a", "dec_conv1b", "dec_conv0"};
enum Layer {
  kEnc0,
  kEnc1,
  kEnc2,
  kEnc3,
  kEnc4,
  kEnc5a,
  kEnc5b,
  kDec4a,
  kDec4b,
  kDec3a,
  kDec3b,
  kDec2a,
  kDec2b,
  kDec1a,
  kDec1b,
  kDec0,
  kLayerCount
};

const Tensor& tensor(const TensorMap& tensors, const std::string& name) {
  const auto it = tensors.find(name);
  if (it == tensors.end()) throw DenoiseError("weights lack tensor '" + name + "'");
  return it->second;
}

ConvWeights conv_weights(const TensorMap& tensors, const std::string& name, int in_channels) {
  const Tensor& w = tensor(tensors, name + ".weight");
  const Tensor& b = tensor(tensors, name + ".bias");
  if (w.layout != "oihw" || w.dims.size() != 4 || w.dims[2] != 3 || w.dims[3] != 3)
    throw DenoiseError("weights '" + name + ".weight' are not a 3x3 convolution");
  if (b.dims.size() != 1 || b.dims[0] != w.dims[0])
    throw DenoiseError("bias '" + name + ".bias' does not match its weights");
  if (w.dims[1] != in_channels)
    throw DenoiseError("weights '" + name + ".weight' read " + std::to_string(w.dims[1]) + " channels, not " +
                       std::to_string(in_channels));
  return {w.dims[0], w.dims[1], w.values, b.values};
}

// Splits a convolution over [first, second] concatenated channels into one per part (the bias stays with
// the first).
ConvLayer split_concat(const std::string& name, ConvWeights both, int first) {
  ConvWeights a{both.out_channels, first, {}, std::move(both.bias)};
  ConvWeights b{both.out_channels, both.in_channels - first, {}, {}};
  const size_t plane = 9;
  for (int o = 0; o < both.out_channels; ++o) {
    const auto row = both.weights.begin() + ptrdiff_t(size_t(o) * size_t(both.in_channels) * plane);
    a.weights.insert(a.weights.end(), row, row + ptrdiff_t(size_t(first) * plane));
    b.weights.insert(b.weights.end(), row + ptrdiff_t(size_t(first) * plane),
                     row + ptrdiff_t(size_t(both.in_channels) * plane));
  }
  return {name, std::move(a), std::move(b)};
}

}  // namespace

// The CPU engine, and each convolution's weights in the layouts oneDNN chose for them (reordered once).
struct UNet::Engine {
  dnnl::engine cpu{dnnl::engine::kind::cpu, 0};
  std::mutex mutex;
  std::map<const ConvWeights*, std::vector<memory>> weights;
};

UNet::UNet(const TensorMap& tensors, int input_channels)
    : input_channels_(input_channels), engine_(std::make_unique<Engine>()) {
  int channels = input_channels;
  std::vector<int> level_channels;  // what each pooled level (and the input) hands the decoder
  level_channels.push_back(input_channels);
  for (int i = 0; i < kLayerCount; ++i) {
    const std::string name = kLayerNames[i];
    const bool concat = i == kDec4a || i == kDec3a || i == kDec2a || i == kDec1a;
    int skip = 0;
    if (concat) {
      skip = level_channels.back();
      level_channels.pop_back();
    }
    ConvWeights w = conv_weights(tensors, name, channels + skip);
    channels = w.out_channels;
    if (i == kEnc1 || i == kEnc2 || i == kEnc3) level_channels.push_back(channels);
    layers_.push_back(concat ? split_concat(name, std::move(w), w.in_channels - skip)
                             : ConvLayer{name, std::move(w), {}});
  }
  if (channels != 3)
    throw DenoiseError("weights' last layer gives " + std::to_string(channels) + " channels, not 3");
}

UNet::~UNet() = default;

namespace {

// One pass of the network on one tile: each step creates its primitive (oneDNN caches them by shape) and
// keeps tensors only as long as a later step reads them.
class Pass {
 public:
  explicit Pass(UNet::Engine& engine) : engine_(engine), cpu_(engine.cpu), stream_(engine.cpu) {}

  memory conv(const ConvLayer& layer, const memory& src, const memory* skip) {
    if (!skip) return conv_part(layer.main, src, nullptr);
    const memory partial = conv_part(layer.skip, *skip, nullptr, false);
    return conv_part(layer.main, src, &partial);
  }

  memory pool(const memory& src) {
    const Dims d = src.get_desc().dims();
    const memory::desc dst_md({d[0], d[1], d[2] / 2, d[3] / 2}, memory::data_type::f32,
                              memory::format_tag::any);
    const dnnl::pooling_forward::desc desc(dnnl::prop_kind::forward_inference, dnnl::algorithm::pooling_max,
                                           src.get_desc(), dst_md, {2, 2}, {2, 2}, {0, 0}, {0, 0});
    return run_simple<dnnl::pooling_forward>(desc, src);
  }

  memory upsample(const memory& src) {
    const Dims d = src.get_desc().dims();
    const memory::desc dst_md({d[0], d[1], d[2] * 2, d[3] * 2}, memory::data_type::f32,
                              memory::format_tag::any);
    const dnnl::resampling_forward::desc desc(dnnl::prop_kind::forward_inference,
                                              dnnl::algorithm::resampling_nearest, src.get_desc(), dst_md);
    return run_simple<dnnl::resampling_forward>(desc, src);
  }

  void copy(const memory& src, const memory& dst) {
    dnnl::reorder(src, dst).execute(stream_, const_cast<memory&>(src), const_cast<memory&>(dst));
    stream_.wait();
  }

 private:
  dnnl::primitive_attr attr() const {
    dnnl::primitive_attr a;
    a.set_scratchpad_mode(dnnl::scratchpad_mode::user);
    return a;
  }

  template <typename Primitive>
  memory run_simple(const typename Primitive::desc& desc, const memory& src) {
    const typename Primitive::primitive_desc pd(desc, attr(), cpu_);
    memory dst(pd.dst_desc(), cpu_);
    memory scratch(pd.scratchpad_desc(), cpu_);
    std::unordered_map<int, memory> args{
        {DNNL_ARG_SRC, src}, {DNNL_ARG_DST, dst}, {DNNL_ARG_SCRATCHPAD, scratch}};
    if (pd.workspace_desc().get_size() > 0)
      args.emplace(DNNL_ARG_WORKSPACE, memory(pd.workspace_desc(), cpu_));
    Primitive(pd).execute(stream_, args);
    stream_.wait();
    return dst;
  }

  // dst = relu(conv(src) + bias [+ accumulate]); without relu when the result is a partial sum.
  memory conv_part(const ConvWeights& w, const memory& src, const memory* accumulate, bool relu = true) {
    const Dims d = src.get_desc().dims();
    const Dims wdims{w.out_channels, w.in_channels, 3, 3};
    const memory::desc w_md(wdims, memory::data_type::f32, memory::format_tag::any);
    const memory::desc dst_md = accumulate ? accumulate->get_desc()
                                           : memory::desc({d[0], w.out_channels, d[2], d[3]},
                                                          memory::data_type::f32, memory::format_tag::any);
    dnnl::primitive_attr a = attr();
    dnnl::post_ops ops;
    if (accumulate) ops.append_sum(1.f);
    if (relu) ops.append_eltwise(1.f, dnnl::algorithm::eltwise_relu, 0.f, 0.f);
    a.set_post_ops(ops);
    // Direct convolution: Winograd (F(2,3)) measured no faster here, and it rounds differently.
    const auto kind = dnnl::prop_kind::forward_inference;
    const auto alg = dnnl::algorithm::convolution_direct;
    const auto desc =
        w.bias.empty()
            ? dnnl::convolution_forward::desc(kind, alg, src.get_desc(), w_md, dst_md, {1, 1}, {1, 1}, {1, 1})
            : dnnl::convolution_forward::desc(
                  kind, alg, src.get_desc(), w_md,
                  memory::desc({w.out_channels}, memory::data_type::f32, memory::format_tag::x), dst_md,
                  {1, 1}, {1, 1}, {1, 1});
    const dnnl::convolution_forward::primitive_desc pd(desc, a, cpu_);

    const memory weights = weights_in(w, pd.weights_desc());
    memory dst = accumulate ? *accumulate : memory(pd.dst_desc(), cpu_);
    memory scratch(pd.scratchpad_desc(), cpu_);
    std::unordered_map<int, memory> args{{DNNL_ARG_SRC, src},
                                         {DNNL_ARG_WEIGHTS, weights},
                                         {DNNL_ARG_DST, dst},
                                         {DNNL_ARG_SCRATCHPAD, scratch}};
    if (!w.bias.empty())
      args.emplace(DNNL_ARG_BIAS, memory({{w.out_channels}, memory::data_type::f32, memory::format_tag::x},
                                         cpu_, const_cast<float*>(w.bias.data())));
    dnnl::convolution_forward(pd).execute(stream_, args);
    stream_.wait();
    return dst;
  }

  // The layer's weights in `layout`, reordered from oihw on first use.
  memory weights_in(const ConvWeights& w, const memory::desc& layout) {
    std::lock_guard lock(engine_.mutex);
    auto& reordered = engine_.weights[&w];
    for (const memory& m : reordered)
      if (m.get_desc() == layout) return m;
    const memory user(
        {{w.out_channels, w.in_channels, 3, 3}, memory::data_type::f32, memory::format_tag::oihw}, cpu_,
        const_cast<float*>(w.weights.data()));
    memory m(layout, cpu_);
    copy(user, m);
    reordered.push_back(m);
    return m;
  }

  UNet::Engine& engine_;
  const dnnl::engine& cpu_;
  dnnl::stream stream_;
};

}  // namespace

void UNet::run(const float* input, int height, int width, float* output) const {
  try {
    Pass pass(*engine_);
    const auto& L = layers_;
    const memory in({{1, input_channels_, height, width}, memory::data_type::f32, memory::format_tag::nchw},
                    engine_->cpu, const_cast<float*>(input));
    // Each assignment to x releases the tensor it replaces: only the pooled skips live across levels.
    memory x = pass.conv(L[kEnc0], in, nullptr);
    x = pass.conv(L[kEnc1], x, nullptr);
    const memory pool1 = pass.pool(x);
    x = pass.conv(L[kEnc2], pool1, nullptr);
    const memory pool2 = pass.pool(x);
    x = pass.conv(L[kEnc3], pool2, nullptr);
    const memory pool3 = pass.pool(x);
    x = pass.conv(L[kEnc4], pool3, nullptr);
    x = pass.pool(x);
    x = pass.conv(L[kEnc5a], x, nullptr);
    x = pass.upsample(pass.conv(L[kEnc5b], x, nullptr));
    x = pass.conv(L[kDec4a], x, &pool3);
    x = pass.upsample(pass.conv(L[kDec4b], x, nullptr));
    x = pass.conv(L[kDec3a], x, &pool2);
    x = pass.upsample(pass.conv(L[kDec3b], x, nullptr));
    x = pass.conv(L[kDec2a], x, &pool1);
    x = pass.upsample(pass.conv(L[kDec2b], x, nullptr));
    x = pass.conv(L[kDec1a], x, &in);
    x = pass.conv(L[kDec1b], x, nullptr);
    x = pass.conv(L[kDec0], x, nullptr);
    const memory out({{1, 3, height, width}, memory::data_type::f32, memory::format_tag::nchw}, engine_->cpu,
                     output);
    pass.copy(x, out);
  } catch (const dnnl::error& e) {
    throw DenoiseError(std::string("the denoising network failed: ") + e.what());
  }
}

}  // namespace lp::denoise
