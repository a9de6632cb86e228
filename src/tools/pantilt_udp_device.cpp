/**
 * \file
 * \brief pantilt_udp_device: a PanTilt device controller on UDP over the simulated motion model.
 *
 * Try the pantilt_udp backend without hardware, or break the link on purpose. SIGUSR1 toggles silence.
 */
#include <pthread.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "ptz_action_server/core/pantilt/pantilt_udp_device.h"

namespace
{
const char* USAGE = R"(usage: pantilt_udp_device [options]

A PanTilt device controller on UDP: executes SET_PARAM / COMMAND frames on a simulated pan-tilt unit and reports
its params (a full params frame in reply to every valid datagram, and every --state-period to the last client).

Options:
  --host HOST            address to listen on (default 127.0.0.1)
  --port PORT            UDP port (default 5000; 0 = any free port)
  --version 1.0|1.1      wire format (default 1.0, the seed's)
  --state-period S       seconds between unsolicited params frames (default 0.1; 0 = replies only)
  --drop RATIO           drop this share of replies (0..1)
  --delay S              delay every reply by S seconds
  --silent               start silent: ignore everything, send nothing (an unplugged device)
  --silent-after S       fall silent S seconds after start
Signals: SIGUSR1 toggles silence; SIGINT / SIGTERM end the program.
)";

[[noreturn]] void fail(const std::string& message)
{
  std::fprintf(stderr, "pantilt_udp_device: %s\n\n%s", message.c_str(), USAGE);
  std::exit(2);
}

double number(const char* text, const char* option)
{
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value >= 0.0))
  {
    fail(std::string(option) + " needs a number >= 0");
  }
  return value;
}
}  // namespace

int main(int argc, char** argv)
{
  cr::pantilt::PanTiltUdpDeviceConfig config;
  config.port = 5000;
  bool silent = false;
  double silent_after = -1.0;
  double drop = 0.0;
  double delay = 0.0;
  for (int index = 1; index < argc; ++index)
  {
    const std::string arg = argv[index];
    if (arg.rfind("__", 0) == 0 || arg.find(":=") != std::string::npos)
    {
      continue;  // roslaunch's __name:= and remappings
    }
    auto value = [&]() -> const char* {
      if (index + 1 >= argc)
      {
        fail(arg + " needs a value");
      }
      return argv[++index];
    };
    if (arg == "--host")
    {
      config.host = value();
    }
    else if (arg == "--port")
    {
      const double port = number(value(), "--port");
      if (port > 65535)
      {
        fail("--port must be 0..65535");
      }
      config.port = static_cast<std::uint16_t>(port);
    }
    else if (arg == "--version")
    {
      if (!cr::pantilt::parseWireVersion(value(), config.version))
      {
        fail("--version must be 1.0 or 1.1");
      }
    }
    else if (arg == "--state-period")
    {
      config.state_period = number(value(), "--state-period");
    }
    else if (arg == "--drop")
    {
      drop = number(value(), "--drop");
    }
    else if (arg == "--delay")
    {
      delay = number(value(), "--delay");
    }
    else if (arg == "--silent")
    {
      silent = true;
    }
    else if (arg == "--silent-after")
    {
      silent_after = number(value(), "--silent-after");
    }
    else if (arg == "-h" || arg == "--help")
    {
      std::printf("%s", USAGE);
      return 0;
    }
    else
    {
      fail("unknown option " + arg);
    }
  }

  // The signals are taken synchronously by the main thread; the device's I/O thread inherits the mask.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGUSR1);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  try
  {
    cr::pantilt::PanTiltUdpDevice device(config);
    device.setSilent(silent);
    device.setDropRatio(drop);
    device.setReplyDelay(delay);
    std::printf("pantilt_udp_device: listening on %s, wire %s, state every %.2f s%s\n",
                device.endpoint().toString().c_str(), cr::pantilt::toString(config.version), config.state_period,
                silent ? ", silent" : "");
    std::fflush(stdout);
    const auto silence_at = std::chrono::steady_clock::now() + std::chrono::duration<double>(silent_after);
    while (true)
    {
      int signal = 0;
      if (silent_after >= 0.0)
      {
        const double left =
            std::max(0.0, std::chrono::duration<double>(silence_at - std::chrono::steady_clock::now()).count());
        timespec timeout{ static_cast<time_t>(left), static_cast<long>((left - static_cast<time_t>(left)) * 1e9) };
        signal = sigtimedwait(&signals, nullptr, &timeout);
        if (signal < 0 && errno == EAGAIN)
        {
          silent_after = -1.0;
          silent = true;
          device.setSilent(true);
          std::printf("pantilt_udp_device: silent\n");
          std::fflush(stdout);
          continue;
        }
      }
      else
      {
        signal = sigwaitinfo(&signals, nullptr);
      }
      if (signal == SIGUSR1)
      {
        silent = !silent;
        device.setSilent(silent);
        std::printf("pantilt_udp_device: %s\n", silent ? "silent" : "answering again");
        std::fflush(stdout);
      }
      else if (signal == SIGINT || signal == SIGTERM)
      {
        break;
      }
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "pantilt_udp_device: %s\n", error.what());
    return 1;
  }
  return 0;
}
