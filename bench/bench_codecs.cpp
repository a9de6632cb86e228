/**
 * \file
 * \brief Codec throughput (Google Benchmark): encode and decode of every protocol's frames.
 */
#include <benchmark/benchmark.h>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace
{
using namespace cr::pantilt;

void PanTiltEncodeSetParam(benchmark::State& state)
{
  const auto format = static_cast<WireFormat>(state.range(0));
  std::uint8_t frame[SET_PARAM_SIZE];
  int size = 0;
  float value = 0.0f;
  for (auto _ : state)
  {
    PanTilt::encodeSetParamCommand(frame, size, PanTiltParam::PAN_ANGLE, value, format);
    value += 0.5f;
    benchmark::DoNotOptimize(frame);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(PanTiltEncodeSetParam)->Arg(0)->Arg(1)->Arg(2);

void PanTiltDecodeCommand(benchmark::State& state)
{
  const auto format = static_cast<WireFormat>(state.range(0));
  std::uint8_t frame[MAX_COMMAND_SIZE];
  int size = 0;
  PanTilt::encodeCommand(frame, size, PanTiltCommand::GO_TO_PAN_TILT_ANGLE, format, 10.0f, -5.0f);
  PanTiltParam param{};
  PanTiltCommand command{};
  float value = 0.0f;
  float second = 0.0f;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(PanTilt::decodeCommand(frame, size, param, command, value, format, &second));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(PanTiltDecodeCommand)->Arg(0)->Arg(1)->Arg(2);

void PanTiltParamsEncodeDecode(benchmark::State& state)
{
  const auto format = static_cast<WireFormat>(state.range(0));
  PanTiltParams params;
  params.panAngle = 12.5f;
  params.tiltAngle = -3.25f;
  std::uint8_t frame[MAX_PARAMS_FRAME_SIZE];
  int size = 0;
  PanTiltParams decoded;
  for (auto _ : state)
  {
    params.encode(frame, sizeof(frame), size, nullptr, format);
    benchmark::DoNotOptimize(decoded.decode(frame, size, format));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * size);
}
BENCHMARK(PanTiltParamsEncodeDecode)->Arg(0)->Arg(1)->Arg(2);
}  // namespace

BENCHMARK_MAIN();
