// Builds the type database lcm-spy decodes with (lcm.spy.LCMTypeDatabase, which scans every jar
// and directory on the classpath for classes with an LCM_FINGERPRINT) without opening its window,
// and reports which of the types named on the command line lcm-spy would decode: a JSON object on
// stdout, a line per type on stderr, exit status 1 when any is missing.
import java.io.DataInput;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import lcm.spy.LCMTypeDatabase;

public class SpyTypeCheck {
  public static void main(String[] types) {
    LCMTypeDatabase database = scanClasspath();
    Map<String, String> decoded = new TreeMap<>();
    List<String> missing = new ArrayList<>();
    for (String type : types) {
      String fingerprint = decodingFingerprint(database, type);
      if (fingerprint == null) {
        missing.add(type);
        System.err.println(type + " missing");
      } else {
        decoded.put(type, fingerprint);
        System.err.println(type + " " + fingerprint);
      }
    }
    System.out.println(toJson(decoded, missing));
    System.exit(missing.isEmpty() ? 0 : 1);
  }

  // The database reports what it found on stdout, which is kept for the JSON.
  static LCMTypeDatabase scanClasspath() {
    PrintStream stdout = System.out;
    System.setOut(System.err);
    try {
      return new LCMTypeDatabase();
    } finally {
      System.setOut(stdout);
    }
  }

  // lcm-spy reads a message's first 8 bytes as its fingerprint, takes the database's class for it
  // and calls its DataInput constructor. The database loads classes with a class loader of its
  // own, so the class it holds is matched by name. Null when lcm-spy would not decode the type.
  static String decodingFingerprint(LCMTypeDatabase database, String type) {
    try {
      long fingerprint = Class.forName(type).getField("LCM_FINGERPRINT").getLong(null);
      Class<?> decoder = database.getClassByFingerprint(fingerprint);
      if (decoder == null || !decoder.getName().equals(type)) {
        return null;
      }
      decoder.getConstructor(DataInput.class);
      return String.format("%016x", fingerprint);
    } catch (ReflectiveOperationException notDecodable) {
      return null;
    }
  }

  // Type names are Java class names: nothing in them needs escaping.
  static String toJson(Map<String, String> decoded, List<String> missing) {
    List<String> pairs = new ArrayList<>();
    decoded.forEach((type, fingerprint) -> pairs.add("\"" + type + "\":\"" + fingerprint + "\""));
    List<String> names = new ArrayList<>();
    missing.forEach(type -> names.add("\"" + type + "\""));
    return "{\"decoded\":{" + String.join(",", pairs) + "},\"missing\":[" + String.join(",", names)
        + "]}";
  }
}
