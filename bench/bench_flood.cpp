/**
 * \file
 * \brief bench_flood: the CPU a flooding device costs. A PanTilt UDP backend against its emulator, which sends its
 * state every 50 ms, once (normally) and then 100 times (a flood), for S seconds each (default 5); prints the state
 * reports the backend took in per second and the CPU of this process (the backend's I/O thread and the emulator's
 * threads together) in % of one core. The session keeps one state snapshot, so nothing queues: the CPU grows with
 * the datagrams, not with the time the flood lasts. Prints figures, asserts nothing.
 *
 * usage: bench_flood [SECONDS]
 */
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace
{
double cpuSeconds()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

long peakRssKiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}
}  // namespace

int main(int argc, char** argv)
{
  using namespace ptz_action_server;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 5.0;
  if (!(seconds > 0.0) || seconds > 600.0)
  {
    std::fprintf(stderr, "usage: bench_flood [SECONDS]  (0 < SECONDS <= 600)\n");
    return 2;
  }
  std::printf("PanTilt over UDP, a state every 50 ms, %.0f s each (CPU: backend and emulator, this process)\n",
              seconds);
  std::printf("%-8s %14s %14s %10s %12s %14s\n", "flood", "states sent/s", "states read/s", "CPU %", "link losses",
              "peak RSS KiB");
  for (unsigned flood : { 1u, 100u })
  {
    PanTiltEmulatorConfig emulator_config;
    emulator_config.state_period = 0.05;
    PanTiltEmulator emulator(emulator_config);
    DeviceConfig<PanTiltProtocol> config;
    config.link.port = emulator.udpPort();
    config.link.local_host = "127.0.0.1";
    std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<PanTiltProtocol>(config);
    backend->start();
    emulator.setFlood(flood);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the flood under way

    const std::uint64_t reports = backend->session().counters().state_reports.value();
    const std::uint64_t sent = emulator.counters().replies_sent;
    const double cpu = cpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_share = 100.0 * (cpuSeconds() - cpu) / wall;
    const double read_rate = static_cast<double>(backend->session().counters().state_reports.value() - reports) / wall;
    const double sent_rate = static_cast<double>(emulator.counters().replies_sent - sent) / wall;
    std::printf("%-8s %14.0f %14.0f %10.1f %12llu %14ld\n", (std::to_string(flood) + "x").c_str(), sent_rate, read_rate,
                cpu_share, static_cast<unsigned long long>(backend->sample().link_losses), peakRssKiB());
    backend->stop();
  }
  return 0;
}
