#include "ptz_action_server/emulators/emulator_main.h"

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>

namespace emulator_main
{
namespace
{
const char* const SERIAL_OPTIONS_HELP = R"(Line options (a pseudo-terminal by default):
  --link PATH            keep this symlink pointing at the pseudo-terminal (default %s)
  --tty PATH             use this existing tty instead of creating a pseudo-terminal
  --baud N               pace bytes at this rate, 8N1 (default 9600)
  --tcp PORT             serve TCP on PORT instead (0 = any free port; one client at a time)
  --host HOST            the address --tcp listens on (default 127.0.0.1)
Faults:
  --silent               start silent: read and ignore everything, send nothing
  --silent-after S       fall silent S seconds after start
  --garble RATIO         replace this share of the sent bytes with random ones (0..1)
  --unplug-after S       close the port (remove the link; stop listening) S seconds after start
  --replug-after S       the port is back (a new pseudo-terminal under the same link) S seconds after start
Signals: SIGUSR1 toggles silence, SIGUSR2 unplugs / replugs; SIGINT / SIGTERM end the program.
  --pid-file PATH        write the program's pid there (for whoever sends the signals)
)";

}  // namespace

void fail(const char* program, const std::string& message, const char* usage)
{
  std::fprintf(stderr, "%s: %s\n\n%s", program, message.c_str(), usage);
  std::exit(2);
}

double number(const char* program, const char* text, const std::string& option, const char* usage)
{
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value >= 0.0))
  {
    fail(program, option + " needs a number >= 0", usage);
  }
  return value;
}

double numberIn(const char* program, const char* text, const std::string& option, double min, double max,
                const char* usage)
{
  const double value = number(program, text, option, usage);
  if (value < min || value > max)
  {
    char range[64];
    std::snprintf(range, sizeof(range), " must be %g..%g", min, max);
    fail(program, option + range, usage);
  }
  return value;
}

std::string choice(const char* program, const char* text, const std::string& option,
                   std::initializer_list<const char*> allowed, const char* usage)
{
  std::string list;
  for (const char* candidate : allowed)
  {
    if (std::string(text) == candidate)
    {
      return text;
    }
    list += (list.empty() ? "" : " or ") + std::string(candidate);
  }
  fail(program, option + " must be " + list, usage);
}

bool isRosArgument(const std::string& argument)
{
  return argument.rfind("__", 0) == 0 || argument.find(":=") != std::string::npos;
}

void parseArguments(int argc, char** argv, const char* program, const std::string& usage,
                    const std::function<bool(const std::string& arg, const Value& value)>& take)
{
  for (int index = 1; index < argc; ++index)
  {
    const std::string arg = argv[index];
    if (isRosArgument(arg))
    {
      continue;
    }
    if (arg == "-h" || arg == "--help")
    {
      std::printf("%s", usage.c_str());
      std::exit(0);
    }
    if (arg == "--pid-file" && index + 1 < argc)
    {
      // For whoever sends the fault signals (a test): written at once, before the device starts.
      std::FILE* file = std::fopen(argv[++index], "w");
      if (file == nullptr)
      {
        fail(program, std::string("cannot write the pid file ") + argv[index], usage.c_str());
      }
      std::fprintf(file, "%d\n", static_cast<int>(::getpid()));
      std::fclose(file);
      continue;
    }
    const Value value = [&]() -> const char* {
      if (index + 1 >= argc)
      {
        fail(program, arg + " needs a value", usage.c_str());
      }
      return argv[++index];
    };
    if (!take(arg, value))
    {
      fail(program, "unknown option " + arg, usage.c_str());
    }
  }
}

bool parseListenOption(const std::string& arg, const Value& value, const char* program, const char* usage,
                       std::string& host, std::uint16_t& port)
{
  if (arg == "--host")
  {
    host = value();
    return true;
  }
  if (arg == "--port")
  {
    port = static_cast<std::uint16_t>(numberIn(program, value(), arg, 0, 65535, usage));
    return true;
  }
  return false;
}

bool parseFaultOption(const std::string& arg, const Value& value, const char* program, const char* usage, bool& silent,
                      Schedule& schedule)
{
  if (arg == "--silent")
  {
    silent = true;
    return true;
  }
  if (arg == "--silent-after")
  {
    schedule.silent_after = number(program, value(), arg, usage);
    return true;
  }
  return false;
}

std::string serialUsage(const char* own, const char* default_link)
{
  char serial_help[2048];
  std::snprintf(serial_help, sizeof(serial_help), SERIAL_OPTIONS_HELP, default_link);
  return std::string(own) + serial_help;
}

bool parseSerialOption(const std::string& arg, const Value& value, const char* program, const char* usage,
                       SerialOptions& options)
{
  if (parseFaultOption(arg, value, program, usage, options.silent, options.schedule))
  {
    return true;
  }
  auto number = [&]() { return emulator_main::number(program, value(), arg, usage); };
  if (arg == "--link")
  {
    options.port.link = value();
  }
  else if (arg == "--tty")
  {
    options.port.tty = value();
    options.port.link.clear();
  }
  else if (arg == "--baud")
  {
    options.port.baud = static_cast<unsigned>(number());
    if (options.port.baud == 0)
    {
      fail(program, "--baud must be > 0", usage);
    }
  }
  else if (arg == "--tcp")
  {
    options.port.kind = ptz_action_server::DevicePortConfig::Kind::TCP;
    options.port.port = static_cast<std::uint16_t>(numberIn(program, value(), arg, 0, 65535, usage));
  }
  else if (arg == "--host")
  {
    options.port.host = value();
  }
  else if (arg == "--garble")
  {
    options.garble = std::min(1.0, number());
  }
  else if (arg == "--unplug-after")
  {
    options.schedule.unplug_after = number();
  }
  else if (arg == "--replug-after")
  {
    options.schedule.replug_after = number();
  }
  else
  {
    return false;
  }
  return true;
}

sigset_t blockSignals()
{
  sigset_t signals;
  sigemptyset(&signals);
  for (int signal : { SIGINT, SIGTERM, SIGUSR1, SIGUSR2 })
  {
    sigaddset(&signals, signal);
  }
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  return signals;
}

void run(const char* program, const sigset_t& signals, const Hooks& hooks, Schedule schedule, bool silent)
{
  using Clock = std::chrono::steady_clock;
  const Clock::time_point started = Clock::now();
  bool plugged = true;
  auto say = [program](const char* what) {
    std::printf("%s: %s\n", program, what);
    std::fflush(stdout);
  };
  auto set_silent = [&](bool value) {
    if (hooks.set_silent)
    {
      silent = value;
      hooks.set_silent(value);
      say(value ? "silent" : "answering again");
    }
  };
  auto set_plugged = [&](bool value) {
    if (hooks.unplug && hooks.replug && plugged != value)
    {
      plugged = value;
      (value ? hooks.replug : hooks.unplug)();
      say(value ? "replugged" : "unplugged");
    }
  };
  while (true)
  {
    double* next = nullptr;
    for (double* deadline :
         { &schedule.silent_after, &schedule.unplug_after, &schedule.replug_after, &schedule.own_fault_after })
    {
      if (*deadline >= 0.0 && (next == nullptr || *deadline < *next))
      {
        next = deadline;
      }
    }
    int signal = 0;
    if (next != nullptr)
    {
      const double left = std::max(0.0, *next - std::chrono::duration<double>(Clock::now() - started).count());
      timespec timeout{ static_cast<time_t>(left), static_cast<long>((left - static_cast<time_t>(left)) * 1e9) };
      signal = sigtimedwait(&signals, nullptr, &timeout);
      if (signal < 0 && errno == EAGAIN)
      {
        if (next == &schedule.silent_after)
        {
          set_silent(true);
        }
        else if (next == &schedule.own_fault_after)
        {
          if (hooks.own_fault)
          {
            hooks.own_fault();
          }
        }
        else
        {
          set_plugged(next == &schedule.replug_after);
        }
        *next = -1.0;
        continue;
      }
    }
    else
    {
      signal = sigwaitinfo(&signals, nullptr);
    }
    if (signal == SIGUSR1)
    {
      set_silent(!silent);
    }
    else if (signal == SIGUSR2)
    {
      set_plugged(!plugged);
    }
    else if (signal == SIGINT || signal == SIGTERM)
    {
      return;
    }
  }
}

int runLine(const char* program, const SerialOptions& options, const std::string& detail,
            const std::function<OpenedLine()>& open)
{
  const sigset_t signals = blockSignals();
  try
  {
    const OpenedLine device = open();
    device.port->setSilent(options.silent);
    device.port->setGarbleRatio(options.garble);
    if (options.port.kind != ptz_action_server::DevicePortConfig::Kind::PTY)
    {
      const bool tcp = options.port.kind == ptz_action_server::DevicePortConfig::Kind::TCP;
      std::printf("%s: listening on %s %s%s%s\n", program, tcp ? "tcp" : "udp", device.path.c_str(), detail.c_str(),
                  options.silent ? ", silent" : "");
    }
    else
    {
      std::printf("%s: %s at %u baud%s%s\n", program, device.path.c_str(), options.port.baud, detail.c_str(),
                  options.silent ? ", silent" : "");
    }
    std::fflush(stdout);
    Hooks hooks;
    hooks.set_silent = [&device](bool silent) { device.port->setSilent(silent); };
    hooks.unplug = device.unplug;
    hooks.replug = device.replug;
    run(program, signals, hooks, options.schedule, options.silent);
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", program, error.what());
    return 1;
  }
  return 0;
}

}  // namespace emulator_main
