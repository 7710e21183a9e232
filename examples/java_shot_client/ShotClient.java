// examples/shot_client/shot_client.cc in Java: the cue ball's state on TABLE_STATE and a
// SHOT_REQUEST to a running planner_node, sent again every half second until its CUE_COMMAND
// arrives, printed as one JSON object.
//
//   run_java_shot_client [--lcm-url URL] [--from X,Y] [--to X,Y] [--timeout SECONDS]
//
// Exit status as the C++ client's: 0 a plan, 3 refused, 1 no answer, 2 a bad command line.
import billiard.ball_state_t;
import billiard.cue_command_t;
import billiard.shot_request_t;
import billiard.table_state_t;
import java.io.IOException;
import lcm.lcm.LCM;
import lcm.lcm.LCMDataInputStream;
import lcm.lcm.LCMSubscriber;

public class ShotClient {
  private static double[] point(String option, String text) {
    String[] parts = text.split(",");
    if (parts.length != 2)
      usage("bad " + option + " '" + text + "'");
    try {
      return new double[] {Double.parseDouble(parts[0]), Double.parseDouble(parts[1])};
    } catch (NumberFormatException e) {
      usage("bad " + option + " '" + text + "'");
      return null;
    }
  }

  private static void usage(String why) {
    System.err.println("ShotClient: " + why);
    System.exit(2);
  }

  private static String json(String text) {
    return "\"" + text.replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
  }

  public static void main(String[] args) throws IOException, InterruptedException {
    String url = null; // LCM's default, LCM_DEFAULT_URL when set
    double[] from = {0.5, 0.5}, to = {1.5, 0.8};
    double timeoutS = 10.0;
    for (int i = 0; i < args.length; i += 2) {
      if (i + 1 >= args.length)
        usage("unknown argument or missing value '" + args[i] + "'");
      switch (args[i]) {
        case "--lcm-url":
          url = args[i + 1];
          break;
        case "--from":
          from = point(args[i], args[i + 1]);
          break;
        case "--to":
          to = point(args[i], args[i + 1]);
          break;
        case "--timeout":
          timeoutS = Double.parseDouble(args[i + 1]);
          break;
        default:
          usage("unknown argument '" + args[i] + "'");
      }
    }
    LCM lcm = url == null ? new LCM() : new LCM(url);

    long utime = System.currentTimeMillis() * 1000;
    ball_state_t ball = new ball_state_t();
    ball.utime = utime;
    ball.ball_id = 0;
    ball.position = new double[] {from[0], from[1]};
    ball.ball_class = ball_state_t.CLASS_CUE;
    ball.class_confidence = 1.0f;
    table_state_t state = new table_state_t();
    state.utime = utime;
    state.num_balls = 1;
    state.balls = new ball_state_t[] {ball};

    shot_request_t request = new shot_request_t();
    request.utime = utime;
    request.request_id = utime % 1000000000L;
    request.ball_id = 0;
    request.target = new double[] {to[0], to[1]};
    request.final_speed = 0.0;
    request.spin = shot_request_t.SPIN_NATURAL;
    // One ball to a point (MODE_TO_POINT, the default); Java's strings start null, which an LCM
    // encoder cannot write.
    request.mode = shot_request_t.MODE_TO_POINT;
    request.pocket = "";
    request.player = "";  // empty: the planner node's own player (a match names one)

    final cue_command_t[] answer = {null};
    lcm.subscribe("CUE_COMMAND", new LCMSubscriber() {
      public void messageReceived(LCM lcm, String channel, LCMDataInputStream in) {
        try {
          cue_command_t c = new cue_command_t(in);
          synchronized (answer) {
            if (c.request_id == request.request_id) {
              answer[0] = c;
              answer.notifyAll();
            }
          }
        } catch (IOException e) {
          // not a cue_command_t: not our answer
        }
      }
    });
    long deadline = System.nanoTime() + (long) (timeoutS * 1e9);
    synchronized (answer) {
      while (answer[0] == null && System.nanoTime() < deadline) {
        lcm.publish("TABLE_STATE", state);
        lcm.publish("SHOT_REQUEST", request);
        answer.wait(500);
      }
    }
    cue_command_t c = answer[0];
    if (c == null) {
      System.err.println(
          "ShotClient: no CUE_COMMAND from a planner_node within " + timeoutS + " s");
      System.exit(1);
    }
    System.out.println("{\"request_id\":" + c.request_id + ",\"status\":" + c.status
        + ",\"reason\":" + json(c.reason) + ",\"cue\":{\"speed\":" + c.cue_speed + ",\"heading\":"
        + c.heading + ",\"tip_side\":" + c.tip_side + ",\"tip_height\":" + c.tip_height
        + ",\"elevation\":" + c.elevation + "},\"v0\":[" + c.v0[0] + "," + c.v0[1]
        + "],\"predicted_final\":[" + c.predicted_final[0] + "," + c.predicted_final[1]
        + "],\"refined_miss_m\":" + c.refined_miss_m + ",\"solve_us\":" + c.solve_us + "}");
    System.exit(c.status == cue_command_t.STATUS_OK ? 0 : 3);
  }
}
