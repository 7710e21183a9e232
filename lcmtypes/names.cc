#include "lcmtypes/names.h"

#include <iterator>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"

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
    case cue_command_t::STATUS_NO_SUCH_BALL:
      return "no_such_ball";
    case cue_command_t::STATUS_NO_SUCH_POCKET:
      return "no_such_pocket";
    case cue_command_t::STATUS_BLOCKED:
      return "blocked";
    case cue_command_t::STATUS_TOO_THIN:
      return "too_thin";
    case cue_command_t::STATUS_NO_STROKE:
      return "no_stroke";
    case cue_command_t::STATUS_TARGET_UNREACHABLE:
      return "target_unreachable";
    case cue_command_t::STATUS_CUE_BLOCKED:
      return "cue_blocked";
    case cue_command_t::STATUS_NOT_AT_REST:
      return "not_at_rest";
  }
  return "status " + std::to_string(status);
}

std::string PotKindName(std::int8_t kind) {
  switch (kind) {
    case shot_request_t::KIND_ANY:
      return "any";
    case shot_request_t::KIND_DIRECT:
      return "direct";
    case shot_request_t::KIND_BANK:
      return "bank";
    case shot_request_t::KIND_KICK:
      return "kick";
    case shot_request_t::KIND_CURVE:
      return "curve";
  }
  return "kind " + std::to_string(kind);
}

namespace {

// The rulesets by their RULES_* constant, in its order.
constexpr const char* kShotRules[] = {"any", "nine-ball", "eight-ball", "eight-ball-solids",
                                      "eight-ball-stripes"};
static_assert(shot_request_t::RULES_EIGHT_BALL_STRIPES + 1 == std::size(kShotRules));

}  // namespace

std::string ShotRulesName(std::int8_t rules) {
  return rules >= 0 && rules < static_cast<int>(std::size(kShotRules)) ? kShotRules[rules] : "";
}

std::int8_t ShotRulesCode(const std::string& name) {
  for (std::size_t code = 0; code < std::size(kShotRules); ++code) {
    if (name == kShotRules[code]) return static_cast<std::int8_t>(code);
  }
  return -1;
}

}  // namespace billiard::messages
