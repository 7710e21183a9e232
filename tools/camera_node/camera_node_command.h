// build/bin/camera_node's command line: one source (--device, --video or --images), its pace
// and encoding, checked, and the node run with them until SIGINT or SIGTERM
// (camera_node_main.cc is the few lines that join them).
//
// Exit statuses (docs/exit-codes.md): 2 for a bad command line and for a source whose path is
// not there (a video file or a directory that does not exist, a device path that does not),
// before LCM is opened; 1 when LCM cannot be opened; 0 when a signal stops the node. A source
// that is there but fails (a file no backend reads, a video cut short, a camera that stalls) is
// one line on stderr and source_state 3 in NODE_STATUS, and the node stays up; with
// --exit-at-end it exits at the source's end instead, 0 after a whole video or directory, 1
// after a failure.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "tools/camera_node/frame_source.h"

namespace billiard::camera_node {

struct CameraNodeCommandLine {
  std::string device, video, images;  // exactly one
  double fps = 0.0;
  int width = 0, height = 0;
  int jpeg_quality = 90;
  double stall_timeout = 5.0;  // [s]
  bool loop = false;
  bool exit_at_end = false;
  std::string lcm_url;  // empty: $LCM_DEFAULT_URL, else LCM's default
};

// Adds the node's options to `app`, filling `line` when it parses.
void AddCameraNodeOptions(CLI::App& app, CameraNodeCommandLine* line);

// The source the command line names.
SourceSpec SourceOf(const CameraNodeCommandLine& line);

// Runs the node (the statuses above).
int RunCameraNodeCommand(const CameraNodeCommandLine& line);

}  // namespace billiard::camera_node
