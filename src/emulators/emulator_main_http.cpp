/**
 * \file
 * \brief What the emulated IP cameras (axis_camera_emulator, onvif_camera_emulator) share of emulator_main.h: the
 * HTTP options, their faults, and the start-up and signal loop of an HttpCameraServer.
 */
#include "ptz_action_server/emulators/emulator_main.h"

#include <cstdio>

namespace emulator_main
{
namespace
{
const char* const HTTP_OPTIONS_HELP = R"(HTTP options:
  --host HOST            address to listen on (default 127.0.0.1)
  --port PORT            port (default %u; 0 = any free port)
  --user NAME            the user the camera knows (default root)
  --password TEXT        its password (default pass)
  --auth MODE            digest (default), basic or none
  --nonce-uses N         a digest nonce goes stale after N requests (default 0: never)
  --tls                  serve https with a self-signed certificate made at start (EC P-256, for 127.0.0.1 and
                         localhost); prints its SHA-256 fingerprint (the backend's tls_fingerprint)
  --cert-file PATH       with --tls: write the certificate there, PEM (the backend's ca_file)
  --secrets-file PATH    append every credential-derived value requests carried there, one a line (Digest
                         nonces, responses, cnonces; WS-Security Nonces and PasswordDigests): for leak tests
)";
}  // namespace

const char* const HTTP_FAULTS_HELP = R"(Faults:
  --delay S              answer every request S seconds late
  --http-error CODE      answer every request with this status (e.g. 500)
  --silent               start silent: read requests, never answer
  --silent-after S       fall silent S seconds after start
Signals: SIGUSR1 toggles silence, SIGUSR2 drops every connection; SIGINT / SIGTERM end the program.
  --pid-file PATH        write the program's pid there (for whoever sends the signals)
)";

std::string httpCameraUsage(const char* own, unsigned default_port)
{
  char help[2048];
  std::snprintf(help, sizeof(help), HTTP_OPTIONS_HELP, default_port);
  return std::string(own) + help + HTTP_FAULTS_HELP;
}

bool parseHttpCameraOption(const std::string& arg, const Value& value, const char* program, const char* usage,
                           HttpCameraOptions& options)
{
  using ptz_action_server::HttpAuth;
  if (parseListenOption(arg, value, program, usage, options.http.host, options.http.port) ||
      parseFaultOption(arg, value, program, usage, options.silent, options.schedule))
  {
    return true;
  }
  if (arg == "--user")
  {
    options.http.username = value();
  }
  else if (arg == "--password")
  {
    options.http.password = value();
  }
  else if (arg == "--auth")
  {
    const std::string auth = choice(program, value(), arg, { "digest", "basic", "none" }, usage);
    options.http.auth = auth == "digest" ? HttpAuth::DIGEST : auth == "basic" ? HttpAuth::BASIC : HttpAuth::NONE;
  }
  else if (arg == "--nonce-uses")
  {
    options.http.nonce_uses = static_cast<unsigned>(numberIn(program, value(), arg, 0, 1e9, usage));
  }
  else if (arg == "--tls")
  {
    options.http.tls = true;
  }
  else if (arg == "--cert-file")
  {
    options.certificate_file = value();
  }
  else if (arg == "--secrets-file")
  {
    options.http.secrets_file = value();
  }
  else if (arg == "--delay")
  {
    options.delay = number(program, value(), arg, usage);
  }
  else if (arg == "--http-error")
  {
    options.error_status = static_cast<unsigned>(numberIn(program, value(), arg, 100, 599, usage));
  }
  else
  {
    return false;
  }
  return true;
}

int runHttpCamera(const char* program, const sigset_t& signals, ptz_action_server::HttpCameraServer& server,
                  const HttpCameraOptions& options, const std::string& start_line)
{
  if (!options.certificate_file.empty() && !options.http.tls)
  {
    std::fprintf(stderr, "%s: --cert-file needs --tls\n", program);
    return 2;
  }
  server.setSilent(options.silent);
  server.setDelay(options.delay);
  server.setErrorStatus(options.error_status);
  std::printf("%s: listening on %s (%s, user %s)%s%s\n", program, server.url().c_str(), start_line.c_str(),
              options.http.username.c_str(), options.silent ? ", silent" : "",
              options.error_status != 0 ? ", answering every request with an error status" : "");
  if (options.http.tls)
  {
    std::printf("%s: TLS certificate SHA-256 fingerprint %s\n", program, server.fingerprint().c_str());
    if (!options.certificate_file.empty())
    {
      server.writeCertificate(options.certificate_file);
      std::printf("%s: certificate written to %s\n", program, options.certificate_file.c_str());
    }
  }
  std::fflush(stdout);
  Hooks hooks;
  hooks.set_silent = [&server](bool silent) { server.setSilent(silent); };
  // SIGUSR2 drops the connections; the client reconnects, so "replug" has nothing to do.
  hooks.unplug = [&server] { server.dropConnections(); };
  hooks.replug = [] {};
  run(program, signals, hooks, options.schedule, options.silent);
  return 0;
}

}  // namespace emulator_main
