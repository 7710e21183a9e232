#include "lcmtypes/message_checks.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace billiard::messages {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class Message>
std::vector<std::uint8_t> Encode(const Message& m) {
  std::vector<std::uint8_t> bytes(m.getEncodedSize());
  EXPECT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return bytes;
}

void PutInt32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<std::uint8_t>(v >> (24 - 8 * i));
}

ball_state_t Ball(std::int32_t id) {
  ball_state_t b{};
  b.utime = 5;
  b.ball_id = id;
  b.position[0] = 0.6;
  b.position[1] = 0.5;
  return b;
}

table_state_t Table() {
  table_state_t m{};
  m.utime = 5;
  m.balls = {Ball(0), Ball(3)};
  m.num_balls = 2;
  return m;
}

cue_command_t Command() {
  cue_command_t m{};
  m.utime = 9;
  m.request_id = 4;
  m.cue_speed = 1.5;
  m.path = {{0.1, 0.2}, {0.3, 0.4}};
  m.num_path_points = 2;
  return m;
}

// A pot request: ball 7 into the lower-left pocket, the cue ball left near a point.
shot_request_t PotRequest() {
  shot_request_t m{};
  m.utime = 9;
  m.request_id = 4;
  m.mode = shot_request_t::MODE_POT;
  m.object_ball_id = 7;
  m.pocket = "lower_left";
  m.kind = shot_request_t::KIND_BANK;
  m.has_cue_target = 1;
  m.cue_target[0] = 1.2;
  m.cue_target[1] = 0.6;
  m.cue_radius = 0.05;
  return m;
}

// Its answer: the paths of the cue ball and of ball 7.
cue_command_t PotCommand() {
  cue_command_t m = Command();
  m.mode = shot_request_t::MODE_POT;
  m.object_ball_id = 7;
  m.pocket = "lower_left";
  m.kind = shot_request_t::KIND_DIRECT;
  m.margin_deg[0] = 0.4;
  m.margin_deg[1] = 0.3;
  m.speed_window[0] = 0.9;
  m.speed_window[1] = 2.5;
  m.cue_rest[0] = 1.2;
  m.cue_rest[1] = 0.6;
  ball_path_t cue{0, 2, {{0.1, 0.2}, {0.3, 0.4}}};
  ball_path_t seven{7, 3, {{0.5, 0.5}, {0.3, 0.3}, {0.05, 0.05}}};
  m.ball_paths = {cue, seven};
  m.num_ball_paths = 2;
  return m;
}

image_t Image() {
  image_t m{};
  m.utime = 1;
  m.width = 4;
  m.height = 2;
  m.row_stride = 4;
  m.pixelformat = image_t::PIXEL_FORMAT_GRAY;
  m.data.assign(8, 7);
  m.size = 8;
  return m;
}

node_status_t Status() {
  node_status_t m{};
  m.utime = 1;
  m.node = "planner_node";
  m.params = "pool";
  m.params_hash = "0123456789abcdef";
  m.version = "0.1.0";
  m.last_error = "";
  m.counter_names = {"busy", "stale_state"};
  m.counter_values = {3, 4};
  m.num_counters = 2;
  return m;
}

// Every valid message decodes to itself; every prefix of it, and it with a byte after it, is
// refused with a reason.
template <class Message>
void ExpectOnlyTheWholePayloadDecodes(const Message& m) {
  std::vector<std::uint8_t> bytes = Encode(m);
  Message out;
  ASSERT_EQ(DecodeChecked(bytes.data(), bytes.size(), out), "");
  EXPECT_EQ(Encode(out), bytes);
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_NE(Decode(bytes.data(), n, out), "") << n << " of " << bytes.size() << " bytes";
  }
  bytes.push_back(0);
  EXPECT_NE(Decode(bytes.data(), bytes.size(), out), "");
}

TEST(MessageChecks, OnlyTheWholePayloadDecodes) {
  ExpectOnlyTheWholePayloadDecodes(Table());
  ExpectOnlyTheWholePayloadDecodes(shot_request_t{});
  ExpectOnlyTheWholePayloadDecodes(Command());
  ExpectOnlyTheWholePayloadDecodes(PotRequest());
  ExpectOnlyTheWholePayloadDecodes(PotCommand());
  ExpectOnlyTheWholePayloadDecodes(Image());
  ExpectOnlyTheWholePayloadDecodes(Status());
}

TEST(MessageChecks, AnotherTypeIsRefusedByItsHash) {
  const std::vector<std::uint8_t> bytes = Encode(shot_request_t{});
  table_state_t table;
  EXPECT_NE(Decode(bytes.data(), bytes.size(), table), "");
}

// The counts lcm-gen's decoders would allocate from before reading a byte of what they count.
TEST(MessageChecks, CountsThatLieAreRefusedBeforeAnythingIsAllocated) {
  std::vector<std::uint8_t> table = Encode(Table());
  for (std::uint32_t count : {0xffffffffu, 0x7fffffffu, 3u, 65u}) {
    PutInt32(table, 16, count);
    table_state_t out;
    const std::string why = Decode(table.data(), table.size(), out);
    EXPECT_NE(why.find("num_balls"), std::string::npos) << count << ": " << why;
  }

  std::vector<std::uint8_t> image = Encode(Image());
  for (std::uint32_t size : {0xffffffffu, 0x7fffffffu, 9u}) {
    PutInt32(image, 32, size);
    image_t out;
    EXPECT_NE(Decode(image.data(), image.size(), out).find("image size"), std::string::npos);
  }

  // cue_command_t: the path count (after 8 + 116 bytes) and the reason's length, which lcm-gen
  // passes to std::string::assign minus one (a length of 0 would read 2^64 - 1 bytes).
  std::vector<std::uint8_t> command = Encode(Command());
  constexpr std::size_t kPathCount = 124;
  PutInt32(command, kPathCount, 0x40000000u);
  cue_command_t out;
  EXPECT_NE(Decode(command.data(), command.size(), out).find("num_path_points"), std::string::npos);
  command = Encode(Command());
  // An empty reason (length 1, then NUL), then the safety flag's byte.
  const std::size_t reason_length = command.size() - 6;
  for (std::uint32_t length : {0u, 0xffffffffu, 2u, 1000u}) {
    PutInt32(command, reason_length, length);
    EXPECT_NE(Decode(command.data(), command.size(), out).find("reason"), std::string::npos)
        << length;
  }
  PutInt32(command, reason_length, 1);
  command[command.size() - 2] = 'x';  // not terminated
  EXPECT_NE(Decode(command.data(), command.size(), out).find("not terminated"), std::string::npos);

  // A pot's ball paths: their count, and each path's, after the pocket. Two paths of a cue
  // command with an empty reason end 2 (points) x 16 + 8, 3 x 16 + 8, 33 (a choice's
  // probability, its error and the cue placement), 1 (status), 5 (reason) and 1 byte (safety)
  // before the end.
  const std::size_t pot_tail = 2 * 16 + 8 + 3 * 16 + 8 + 33 + 1 + 5 + 1;
  const std::size_t ball_paths = Encode(PotCommand()).size() - pot_tail - 4;
  for (std::uint32_t count : {0xffffffffu, 65u, 0x40000000u}) {
    command = Encode(PotCommand());
    PutInt32(command, ball_paths, count);
    EXPECT_NE(Decode(command.data(), command.size(), out).find("num_ball_paths"), std::string::npos)
        << count;
  }
  command = Encode(PotCommand());
  PutInt32(command, ball_paths, 3);  // a third path, read from the status and the reason
  EXPECT_NE(Decode(command.data(), command.size(), out), "");
  for (std::uint32_t count : {0xffffffffu, 0x40000000u, 100u}) {
    command = Encode(PotCommand());
    PutInt32(command, ball_paths + 8, count);  // the cue ball's path's num_points
    EXPECT_NE(Decode(command.data(), command.size(), out).find("ball path"), std::string::npos)
        << count;
  }
  // A request's pocket: the string that makes shot_request_t a type of variable size.
  std::vector<std::uint8_t> request = Encode(PotRequest());
  const std::size_t pocket_length = 8 + 8 + 8 + 4 + 1 + 3 * 8 + 1 + 2 * 8 + 1 + 4 + 1;
  for (std::uint32_t length : {0u, 0xffffffffu, 1000u}) {
    PutInt32(request, pocket_length, length);
    shot_request_t decoded;
    EXPECT_NE(Decode(request.data(), request.size(), decoded).find("pocket"), std::string::npos)
        << length;
  }
}

// Found by fuzz/fuzz_node_status and fuzz_cue_command: lcm-gen's decoder keeps the bytes after a
// NUL inside a string and its encoder (strlen) drops them, so a node that forwarded or logged
// such a message sent another one, shorter than the size it announced.
TEST(MessageChecks, StringsWithANulInsideAreRefused) {
  std::vector<std::uint8_t> status = Encode(Status());
  constexpr std::size_t kNodeBytes = 20;  // after the hash, utime and the node's length
  status[kNodeBytes + 3] = 0;             // "pla\0ner_node"
  node_status_t decoded_status;
  EXPECT_NE(Decode(status.data(), status.size(), decoded_status).find("node has a NUL"),
            std::string::npos);

  cue_command_t refused = Command();
  refused.reason = "queue full";
  std::vector<std::uint8_t> command = Encode(refused);
  command[command.size() - 6] = 0;  // "queue\0full"
  cue_command_t decoded_command;
  EXPECT_NE(Decode(command.data(), command.size(), decoded_command).find("reason has a NUL"),
            std::string::npos);
}

TEST(MessageChecks, TableStateMeaning) {
  EXPECT_EQ(Check(Table()), "");
  const auto refused = [](auto edit) {
    table_state_t m = Table();
    edit(m);
    return Check(m);
  };
  EXPECT_NE(refused([](table_state_t& m) { m.utime = -1; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[1].ball_id = -2; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[1].ball_id = 0; }).find("twice"),
            std::string::npos);
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].utime = 6; }).find("newer"),
            std::string::npos);
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].position[1] = kNaN; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].velocity[0] = 1e300; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].spin[2] = -kNaN; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].spin[2] = 2e4; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].covariance[13] = kNaN; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].covariance[16] = -1.0; }), "");
  EXPECT_NE(refused([](table_state_t& m) { m.balls[0].position[0] = 1e3; }), "");
  // Classes: unknown, pool's 1-15, the cue ball and the named colours; confidences in [0, 1].
  for (const int8_t known :
       {ball_state_t::CLASS_UNKNOWN, int8_t{1}, int8_t{15}, ball_state_t::CLASS_CUE,
        ball_state_t::CLASS_RED, ball_state_t::CLASS_BLACK}) {
    EXPECT_EQ(refused([&](table_state_t& m) { m.balls[0].ball_class = known; }), "") << +known;
  }
  for (const int8_t unknown : {int8_t{-1}, int8_t{17}, int8_t{19}, int8_t{27}}) {
    EXPECT_NE(refused([&](table_state_t& m) { m.balls[0].ball_class = unknown; }).find("class"),
              std::string::npos)
        << +unknown;
  }
  EXPECT_EQ(refused([](table_state_t& m) { m.balls[0].class_confidence = 1.0f; }), "");
  for (const float bad : {-0.1f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
    EXPECT_NE(refused([&](table_state_t& m) { m.balls[0].class_confidence = bad; }), "") << bad;
  }
}

TEST(MessageChecks, ShotRequestMeaning) {
  const auto refused = [](auto edit) {
    shot_request_t m{};
    edit(m);
    return Check(m);
  };
  EXPECT_EQ(refused([](shot_request_t&) {}), "");
  EXPECT_EQ(refused([](shot_request_t& m) { m.slide_length = kNaN; }), "")
      << "slide_length means nothing without SPIN_SLIDE";
  EXPECT_NE(refused([](shot_request_t& m) {
              m.spin = shot_request_t::SPIN_SLIDE;
              m.slide_length = kNaN;
            }),
            "");
  EXPECT_NE(refused([](shot_request_t& m) { m.spin = 5; }).find("spin"), std::string::npos);
  EXPECT_NE(refused([](shot_request_t& m) { m.spin = -1; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.request_id = -1; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.ball_id = -2; }), "");
  // By class: a known class, not CLASS_UNKNOWN.
  EXPECT_NE(refused([](shot_request_t& m) { m.ball_id = shot_request_t::BALL_BY_CLASS; }), "");
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.ball_id = shot_request_t::BALL_BY_CLASS;
              m.ball_class = ball_state_t::CLASS_CUE;
            }),
            "");
  EXPECT_NE(refused([](shot_request_t& m) {
              m.ball_id = shot_request_t::BALL_BY_CLASS;
              m.ball_class = 30;
            }),
            "");
  EXPECT_NE(refused([](shot_request_t& m) { m.utime = -1; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.target[0] = kNaN; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.final_speed = -0.1; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.final_speed = 1e9; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.side_spin = 1e9; }), "");
}

TEST(MessageChecks, PotRequestMeaning) {
  const auto refused = [](auto edit) {
    shot_request_t m = PotRequest();
    edit(m);
    return Check(m);
  };
  EXPECT_EQ(refused([](shot_request_t&) {}), "");
  EXPECT_EQ(refused([](shot_request_t& m) { m.has_cue_target = 0; }), "");
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.has_cue_target = 0;
              m.cue_target[0] = kNaN;
            }),
            "")
      << "the cue-ball target means nothing without has_cue_target";
  EXPECT_NE(refused([](shot_request_t& m) { m.cue_target[1] = kNaN; }).find("non-finite"),
            std::string::npos);
  EXPECT_NE(refused([](shot_request_t& m) { m.cue_radius = kNaN; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.cue_radius = -0.1; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.has_cue_target = 2; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.mode = 4; }).find("mode"), std::string::npos);
  // A break is nine-ball's or eight-ball's.
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_BREAK;
              m.rules = shot_request_t::RULES_EIGHT_BALL;
            }),
            "");
  EXPECT_NE(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_BREAK;
              m.rules = shot_request_t::RULES_EIGHT_BALL_SOLIDS;
            }).find("break"),
            std::string::npos);
  // A choice: rules and ball in hand known, the pot's fields unread.
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_CHOOSE;
              m.rules = shot_request_t::RULES_NINE_BALL;
              m.ball_in_hand = 1;
              m.pocket = "";
            }),
            "");
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_CHOOSE;
              m.rules = shot_request_t::RULES_EIGHT_BALL_STRIPES;
              m.player = "easiest-looking";
            }),
            "");
  EXPECT_NE(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_CHOOSE;
              m.rules = 5;
            }).find("rules"),
            std::string::npos);
  EXPECT_NE(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_CHOOSE;
              m.ball_in_hand = 2;
            }).find("ball_in_hand"),
            std::string::npos);
  EXPECT_NE(refused([](shot_request_t& m) { m.kind = 5; }).find("kind"), std::string::npos);
  EXPECT_NE(refused([](shot_request_t& m) { m.kind = -1; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.pocket = ""; }).find("pocket"), std::string::npos);
  EXPECT_NE(refused([](shot_request_t& m) { m.object_ball_id = -2; }), "");
  EXPECT_NE(refused([](shot_request_t& m) { m.object_ball_id = shot_request_t::BALL_BY_CLASS; }),
            "");
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.object_ball_id = shot_request_t::BALL_BY_CLASS;
              m.object_ball_class = 9;
            }),
            "");
  // The point request's checks hold for a pot too.
  EXPECT_NE(refused([](shot_request_t& m) { m.target[0] = kNaN; }), "");
  // A point request ignores the pot's fields.
  EXPECT_EQ(refused([](shot_request_t& m) {
              m.mode = shot_request_t::MODE_TO_POINT;
              m.pocket = "";
              m.kind = 9;
            }),
            "");
}

TEST(MessageChecks, CueCommandMeaning) {
  EXPECT_EQ(Check(Command()), "");
  const auto refused = [](auto edit) {
    cue_command_t m = Command();
    edit(m);
    return Check(m);
  };
  EXPECT_NE(refused([](cue_command_t& m) { m.status = cue_command_t::STATUS_CUE_BLOCKED + 1; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.status = -1; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.heading = kNaN; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.path[1][0] = kNaN; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.cue_speed = 0.0; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.reason = "but why"; }), "");
  // A refusal carries no stroke.
  EXPECT_NE(refused([](cue_command_t& m) { m.status = cue_command_t::STATUS_BUSY; }), "");
  EXPECT_EQ(refused([](cue_command_t& m) {
              m.status = cue_command_t::STATUS_BUSY;
              m.cue_speed = 0.0;
              m.reason = "queue full";
            }),
            "");
}

TEST(MessageChecks, PotCommandMeaning) {
  EXPECT_EQ(Check(PotCommand()), "");
  const auto refused = [](auto edit) {
    cue_command_t m = PotCommand();
    edit(m);
    return Check(m);
  };
  EXPECT_NE(refused([](cue_command_t& m) { m.margin_deg[1] = kNaN; }).find("non-finite"),
            std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) { m.speed_window[0] = kNaN; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.cue_rest[0] = -kNaN; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.ball_paths[1].points[2][1] = kNaN; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.ball_paths[1].ball_id = 0; }).find("twice"),
            std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) { m.ball_paths[1].ball_id = -1; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.kind = 7; }).find("kind"), std::string::npos);
  // A choice's: a probability, its error and the cue placement.
  EXPECT_EQ(refused([](cue_command_t& m) {
              m.mode = shot_request_t::MODE_CHOOSE;
              m.success_probability = 0.9;
              m.probability_stderr = 0.02;
              m.has_cue_placement = 1;
              m.cue_placement[0] = 0.6;
              m.cue_placement[1] = 0.5;
            }),
            "");
  EXPECT_NE(refused([](cue_command_t& m) { m.success_probability = 1.5; }).find("probability"),
            std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) { m.probability_stderr = -0.1; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.cue_placement[1] = kNaN; }).find("non-finite"),
            std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) { m.has_cue_placement = 2; }), "");
  // Counts that are not the arrays' sizes, or beyond what a receiver decodes: not to be sent.
  EXPECT_NE(refused([](cue_command_t& m) { m.num_ball_paths = 3; }).find("num_ball_paths"),
            std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) { m.ball_paths[0].num_points = 1; }).find("num_points"),
            std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) {
              m.ball_paths[0].points.assign(kMaxPathPoints + 1, {0.1, 0.1});
              m.ball_paths[0].num_points = kMaxPathPoints + 1;
            }),
            "");
  EXPECT_NE(refused([](cue_command_t& m) {
              for (int id = 8; id < 8 + kMaxBallPaths; ++id) m.ball_paths.push_back({id, 0, {}});
              m.num_ball_paths = static_cast<int32_t>(m.ball_paths.size());
            }),
            "");
  EXPECT_NE(refused([](cue_command_t& m) { m.mode = 4; }).find("mode"), std::string::npos);
  EXPECT_NE(refused([](cue_command_t& m) { m.safety = 2; }).find("safety"), std::string::npos);
  // An ok pot says which kind it is, and its windows are windows.
  EXPECT_NE(refused([](cue_command_t& m) { m.kind = shot_request_t::KIND_ANY; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.margin_deg[0] = -0.1; }), "");
  EXPECT_NE(refused([](cue_command_t& m) { m.speed_window[1] = 0.5; }), "");
  // A refused pot: its status and reason, no stroke.
  for (const int8_t status :
       {cue_command_t::STATUS_NO_SUCH_BALL, cue_command_t::STATUS_BLOCKED,
        cue_command_t::STATUS_TARGET_UNREACHABLE, cue_command_t::STATUS_CUE_BLOCKED,
        cue_command_t::STATUS_NOT_AT_REST}) {
    EXPECT_EQ(refused([&](cue_command_t& m) {
                m.status = status;
                m.cue_speed = 0.0;
                m.kind = shot_request_t::KIND_ANY;
                m.reason = "why not";
              }),
              "")
        << +status;
  }
}

TEST(MessageChecks, ImageAndStatusMeaning) {
  EXPECT_EQ(Check(Image()), "");
  image_t image = Image();
  image.width = 0;
  EXPECT_NE(Check(image), "");
  image = Image();
  image.height = kMaxImageSide + 1;
  EXPECT_NE(Check(image), "");
  image = Image();
  image.row_stride = -4;
  EXPECT_NE(Check(image), "");

  EXPECT_EQ(Check(Status()), "");
  node_status_t status = Status();
  status.dropped = -1;
  EXPECT_NE(Check(status), "");
  status = Status();
  status.latency_p99_us = kNaN;
  EXPECT_NE(Check(status), "");
  status = Status();
  status.node = "";
  EXPECT_NE(Check(status), "");
}

}  // namespace
}  // namespace billiard::messages
