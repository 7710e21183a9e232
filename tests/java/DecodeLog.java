// Decodes every message of a recorded loop with the Java classes that lcm-gen --java makes from
// lcmtypes/*.lcm, and prints how many of each channel decoded as one JSON object.
import java.io.EOFException;
import java.io.IOException;
import java.util.TreeMap;
import lcm.logging.Log;

public class DecodeLog {
  public static void main(String[] args) throws IOException {
    Log log = new Log(args[0], "r");
    TreeMap<String, Integer> decoded = new TreeMap<>();
    try {
      while (true) {
        Log.Event e = log.readNext();
        switch (e.channel) {
          case "CAMERA_IMAGE": new billiard.image_t(e.data); break;
          case "TABLE_STATE": case "TABLE_TRUTH": new billiard.table_state_t(e.data); break;
          case "SHOT_REQUEST": new billiard.shot_request_t(e.data); break;
          case "CUE_COMMAND": new billiard.cue_command_t(e.data); break;
          default: continue;
        }
        decoded.merge(e.channel, 1, Integer::sum);
      }
    } catch (EOFException end) {
      // the end of the log
    }
    StringBuilder json = new StringBuilder("{");
    for (String channel : decoded.keySet()) {
      if (json.length() > 1) json.append(',');
      json.append('"').append(channel).append("\":").append(decoded.get(channel));
    }
    System.out.println(json.append('}'));
  }
}
