#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "board/cli/calibrate_command.h"
#include "board/cli/decode_command.h"
#include "board/cli/import_calibration_command.h"
#include "board/cli/import_euroc_command.h"
#include "board/cli/stereo_command.h"
#include "board/config/board_config.h"
#include "board/config/vehicle_setup.h"
#include "board/replay/bench_replay.h"
#include "board/replay/realtime_replay.h"
#include "board/service/run_command.h"
#include "drivers/realtime/heap_policy.h"
#include "vision/iqa/mdm.h"

namespace {

int runReplay(const deepnav::ReplayOptions& options) {
  deepnav::ReplaySummary summary;
  std::string error;
  if (options.realtime && !options.topics_path.empty()) {
    std::fprintf(stderr, "deepnav replay: --topics runs on the bench only: replay its output recording with --realtime\n");
    return 2;
  }
  const bool ok = options.realtime ? deepnav::runRealtimeReplay(options, &summary, &error)
                                   : deepnav::runBenchReplay(options, &summary, &error);
  if (!ok) {
    std::fprintf(stderr, "deepnav replay: %s\n", error.empty() ? "failed (no reason given)" : error.c_str());
    return 1;
  }
  std::printf("%s", deepnav::formatReplaySummary(summary).c_str());
  std::printf("outputs written to %s (replay.mcap, trajectory.tum%s, summary.json)\n", options.out_dir.c_str(),
              summary.has_truth ? ", truth.tum" : "");
  return summary.mismatches == 0 ? 0 : 3;
}

int runIqa(const std::string& path) {
  const cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) {
    std::fprintf(stderr, "deepnav iqa: %s: cannot read the image\n", path.c_str());
    return 1;
  }
  cv::Mat eight_bit = image;
  if (image.depth() != CV_8U) image.convertTo(eight_bit, CV_8U, image.depth() == CV_16U ? 1.0 / 257.0 : 1.0);
  if (eight_bit.channels() == 4) cv::cvtColor(eight_bit, eight_bit, cv::COLOR_BGRA2BGR);
  deepnav::MdmScore mdm;
  deepnav::MdmWorkspace ws;
  if (!deepnav::computeMdm(eight_bit, &mdm, &ws)) {
    std::fprintf(stderr, "deepnav iqa: %s: unsupported image type\n", path.c_str());
    return 1;
  }
  std::printf("{\"f1\": %.6f, \"f2\": %.6f, \"f3\": %.6f, \"score\": %.6f}\n", mdm.f1, mdm.f2, mdm.f3, mdm.score);
  return 0;
}

int runConfig(const std::string& board, bool list) {
  if (list) {
    std::printf("%s", deepnav::describeBoardParams().c_str());
    return 0;
  }
  // The whole vehicle setup: the board and the panel and calibration files it names, as run loads them.
  deepnav::VehicleSetup setup;
  std::string error;
  if (!deepnav::loadVehicleSetup(board, &setup, &error)) {
    std::fprintf(stderr, "deepnav config: %s\n", error.c_str());
    return 2;
  }
  std::printf("%s: valid\n", board.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  deepnav::fixHeapPolicy();  // before any buffer: image-sized blocks mapped, never fragmenting the heap
  CLI::App app{"deepnav: navigation firmware of a deep-sea work-class ROV"};
  app.require_subcommand(1);

  deepnav::ReplayOptions replay;
  bool realtime = false;
  auto* rp = app.add_subcommand("replay", "replay a recording through the nav loop (bench)");
  rp->add_option("recording", replay.input_path, "MCAP recording (with --topics: a ROS 2 MCAP or ROS 1 bag)")
      ->required()
      ->check(CLI::ExistingFile);
  rp->add_option("--topics", replay.topics_path,
                 "topic map of a foreign recording: which topic feeds which sensor (docs/foreign-recordings.md)")
      ->check(CLI::ExistingFile);
  rp->add_option("--out", replay.out_dir, "output directory")->required();
  rp->add_option("--board", replay.board_path, "board file (default: the board stored in the recording)")
      ->check(CLI::ExistingFile);
  rp->add_flag("--realtime", realtime, "play at the recorded speed through the threaded vehicle runtime");
  rp->add_flag("--rerun", replay.rerun, "re-run vision and ticks even if the recording holds outputs");
  rp->add_flag("--record-images", replay.record_images, "copy the stereo images into the output recording");
  rp->add_option("--set", replay.overrides, "board override key=value (repeatable), e.g. vision.vo_mode=all");
  rp->add_option("--workspace-in", replay.workspace_in, "start from a saved workspace (directory)")
      ->check(CLI::ExistingDirectory);
  rp->add_option("--workspace-out", replay.workspace_out, "save the workspace (panel-relative map) at the end");

  deepnav::StereoCommandOptions stereo;
  auto* st = app.add_subcommand("stereo", "dense disparity of a rectified stereo pair, written as PFM");
  st->add_option("left", stereo.left_path, "left image")->required()->check(CLI::ExistingFile);
  st->add_option("right", stereo.right_path, "right image")->required()->check(CLI::ExistingFile);
  st->add_option("--method", stereo.method, "elas | sgbm | sgbm-wls")
      ->check(CLI::IsMember({"elas", "sgbm", "sgbm-wls"}));
  st->add_option("--max-disp", stereo.max_disparity_px, "disparity search range (px)")->check(CLI::Range(1, 256));
  st->add_option("--out", stereo.out_path, "output .pfm (invalid pixels written as +inf)")->required();
  st->add_option("--max-pixels", stereo.max_pixels,
                 "largest image accepted, in pixels (refused before matching; 10 MP takes a 4K pair)")
      ->check(CLI::Range(1LL, 1LL << 40));
  st->add_option("--preset", stereo.elas_preset, "ELAS parameters: dense (every pixel) | robotics (the vehicle's)")
      ->check(CLI::IsMember({"dense", "robotics"}));
  st->add_option("--repeat", stereo.repeat,
                 "match the pair N times and print the min and median compute time (image I/O excluded)")
      ->check(CLI::Range(1, 100000));

  std::string iqa_path;
  auto* iq = app.add_subcommand("iqa", "MDM image quality of one image, as JSON");
  iq->add_option("image", iqa_path, "image file")->required();

  std::string board_path;
  bool list = false;
  auto* cf = app.add_subcommand("config", "validate a board file, or list every parameter");
  cf->add_option("board", board_path, "board.yaml to validate");
  cf->add_flag("--list", list, "print every parameter with unit, default and range (Markdown)");

  deepnav::ServiceOptions run;
  bool validate_only = false;
  auto* rn = app.add_subcommand("run", "the vehicle service: validate the board, then run loop, vision, outputs, recording");
  rn->add_option("--board", run.board_path, "board file")->required();
  rn->add_option("--replay", run.replay_path, "recording to play as the sensors (overrides sources.replay_path)");
  rn->add_option("--record", run.recording_path, "recording file (overrides service.recording_dir)");
  rn->add_flag("--no-record", run.no_recording, "do not record");
  rn->add_option("--duration", run.duration_s, "stop after this many seconds (default: on SIGTERM or end of replay)")
      ->check(CLI::PositiveNumber);
  rn->add_flag("--validate", validate_only, "validate the board (files, devices, outputs) and exit");

  deepnav::CalibrateCommandOptions calibrate;
  auto* cb = app.add_subcommand("calibrate", "stereo calibration from ChArUco or checkerboard views (images or a recording)");
  cb->add_option("--target", calibrate.target_path, "target.yaml (vision/calib/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cb->add_option("inputs", calibrate.inputs, "image files (*left*/*right*), folders of them, or .mcap recordings")
      ->required();
  cb->add_option("--out", calibrate.out_path, "calibration file to write (OpenCV YAML)");
  cb->add_option("--every", calibrate.every, "recordings: use every N-th stereo pair")->check(CLI::Range(1, 100000));

  std::string decode_format, decode_path;
  auto* dc = app.add_subcommand("decode", "decode a sensor capture: one JSON object per message (SI units) on stdout");
  dc->add_option("format", decode_format, "pd0 | pd6 | wl-a50 | nmea0183 | n2k-candump | xsens")
      ->required()
      ->check(CLI::IsMember({"pd0", "pd6", "wl-a50", "nmea0183", "n2k-candump", "xsens"}));
  dc->add_option("file", decode_path, "capture file")->required()->check(CLI::ExistingFile);

  // `deepnav import <format>`: foreign data into deepnav's own files (recordings, calibrations).
  auto* im = app.add_subcommand("import", "convert foreign data (datasets, calibrations) into deepnav's files");
  im->require_subcommand(1);
  deepnav::ImportEurocOptions import_euroc;
  auto* ie = im->add_subcommand("euroc", "an EuRoC/ASL folder (mav0/cam0, cam1, imu0) into a deepnav recording");
  ie->add_option("dir", import_euroc.dir, "dataset folder (holding mav0/)")->required()->check(CLI::ExistingDirectory);
  ie->add_option("--out", import_euroc.out_path, "recording to write (.mcap)")->required();
  ie->add_option("--calibration-out", import_euroc.calibration_out,
                 "also write the stereo calibration (OpenCV YAML, for camera.calibration_file)");
  ie->add_option("--board", import_euroc.board_path, "board stored in the recording (replay then needs no --board)")
      ->check(CLI::ExistingFile);
  ie->add_flag("--skip-missing-images", import_euroc.skip_missing_images,
               "leave out images listed in data.csv whose file is missing (a folder cut short), counted");
  ie->add_option("--duration", import_euroc.duration_s, "import only the first N seconds")->check(CLI::PositiveNumber);
  deepnav::ImportCalibrationOptions import_calibration;
  auto* ic = im->add_subcommand("calibration", "a Kalibr, OpenCV stereo_calib or ROS camera_info stereo calibration "
                                               "into deepnav's calibration file (camera.calibration_file)");
  ic->add_option("--format", import_calibration.format, "kalibr | opencv | camera-info")
      ->required()
      ->check(CLI::IsMember({"kalibr", "opencv", "camera-info"}));
  ic->add_option("files", import_calibration.inputs,
                 "kalibr: camchain.yaml; opencv: intrinsics.yml extrinsics.yml (or one file); camera-info: left.yaml "
                 "right.yaml")
      ->required()
      ->check(CLI::ExistingFile);
  ic->add_option("--out", import_calibration.out_path, "calibration file to write (OpenCV YAML)")->required();
  ic->add_option("--image-size", import_calibration.image_size, "opencv: WIDTHxHEIGHT when the files hold none");

  CLI11_PARSE(app, argc, argv);
  // A library exception that a command lets through (OpenCV asserting on an argument, out of memory) ends
  // it with the command's name and the message, exit code 1, never an abort.
  try {
    if (*rp) {
      replay.realtime = realtime;
      return runReplay(replay);
    }
    if (*rn) return deepnav::runServiceCommand(run, validate_only);
    if (*ie) return deepnav::runImportEurocCommand(import_euroc);
    if (*ic) return deepnav::runImportCalibrationCommand(import_calibration);
    if (*dc) return deepnav::runDecodeCommand(decode_format, decode_path);
    if (*iq) return runIqa(iqa_path);
    if (*st) return deepnav::runStereoCommand(stereo);
    if (*cb) return deepnav::runCalibrateCommand(calibrate);
    if (*cf) {
      if (!list && board_path.empty()) {
        std::fprintf(stderr, "deepnav config: give a board file or --list\n");
        return 2;
      }
      return runConfig(board_path, list);
    }
  } catch (const std::exception& e) {
    const auto commands = app.get_subcommands();
    std::fprintf(stderr, "deepnav %s: failed: %s\n", commands.empty() ? "" : commands.front()->get_name().c_str(),
                 e.what());
    return 1;
  }
  return 0;
}
