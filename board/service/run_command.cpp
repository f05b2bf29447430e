#include "board/service/run_command.h"

#include <cstdio>

#include "board/service/status_text.h"
#include "drivers/systemd/stop_signals.h"

namespace deepnav {

int runServiceCommand(const ServiceOptions& options, bool validate_only) {
  // Before any thread exists, so that every thread inherits the blocked mask and only the main thread
  // takes SIGTERM, synchronously.
  StopSignals signals;
  if (validate_only) {
    VehicleSetup setup;
    ValidatedBoard board;
    std::string error;
    if (!loadVehicleSetup(options.board_path, &setup, &error) ||
        !validateBoard(setup, options.board_path, options.replay_path, &board, &error)) {
      std::fprintf(stderr, "deepnav run: %s\n", error.c_str());
      return 2;
    }
    std::printf("%s: valid (%s)\n", options.board_path.c_str(),
                board.replay_path.empty() ? "devices reachable" : ("replay " + board.replay_path).c_str());
    return 0;
  }
  DeepnavService service;
  std::string error;
  if (!service.init(options, &error)) {
    std::fprintf(stderr, "deepnav run: %s\n", error.c_str());
    return 2;
  }
  const bool ok = service.run(&signals, &error);
  const NavOutput last = service.lastOutput();
  std::fprintf(stderr, "deepnav run: stopped (%s); last: %s\n", service.stopReason().c_str(), formatStatus(last).c_str());
  if (!service.recordingPath().empty()) {
    std::fprintf(stderr, "deepnav run: recording %s closed\n", service.recordingPath().c_str());
  }
  if (!ok) {
    std::fprintf(stderr, "deepnav run: %s\n", error.c_str());
    return 1;
  }
  return 0;
}

}  // namespace deepnav
