// camera_node: camera, video or image frames on CAMERA_IMAGE (camera_node.h), until SIGINT or
// SIGTERM.
#include "lcmtypes/node/node_command_line.h"
#include "tools/camera_node/camera_node_command.h"

int main(int argc, char** argv) {
  CLI::App app{
      "camera_node: frames of a camera, a video file or a directory of images out as "
      "CAMERA_IMAGE"};
  billiard::nodes::OneLineErrors(app, "camera_node");
  billiard::nodes::VersionFlag(app, "camera_node");
  billiard::camera_node::CameraNodeCommandLine line;
  billiard::camera_node::AddCameraNodeOptions(app, &line);
  if (auto status = billiard::nodes::ParseCommandLine(app, argc, argv)) return *status;
  return billiard::camera_node::RunCameraNodeCommand(line);
}
