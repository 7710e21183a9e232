#include "lcmtypes/names.h"

#include "lcmtypes/billiard/cue_command_t.hpp"

namespace billiard::messages {

std::string CueCommandStatusName(std::int8_t status) {
  switch (status) {
    case cue_command_t::STATUS_OK:
      return "ok";
    case cue_command_t::STATUS_INVALID:
      return "invalid";
    case cue_command_t::STATUS_OFF_TABLE:
      return "off_table";
    case cue_command_t::STATUS_UNREACHABLE:
      return "unreachable";
    case cue_command_t::STATUS_NOT_CONVERGED:
      return "not_converged";
    case cue_command_t::STATUS_NO_BALL_STATE:
      return "no_ball_state";
    case cue_command_t::STATUS_STALE_STATE:
      return "stale_state";
    case cue_command_t::STATUS_BUSY:
      return "busy";
  }
  return "status " + std::to_string(status);
}

}  // namespace billiard::messages
