package org.robopro.app.benchmark;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.stream.Stream;
import org.robopro.models.AtomicFiles;
import org.robopro.models.InputException;
import org.robopro.models.JsonMapper;
import org.robopro.models.RobotDescription;
import org.robopro.models.RobotLibrary;
import org.robopro.world.Expected;
import org.robopro.world.Scenario;

/**
 * Concealed campaigns supplied from outside the project (docs/diagnosis-benchmark.md, "Held-out
 * campaigns"): a directory of measurement files {@code NAME.csv} (shared/formats/measurements.md),
 * each beside a truth label {@code NAME.truth.json} that says what the campaign conceals. The
 * benchmark reads them as a user's files and scores the diagnosis against the labels; nothing of
 * how they were made is known to it. The label, JSON:
 * <pre>
 * {
 *   "robot": "irb2000",                 shipped robot name, or a robot file's path relative to the directory
 *   "sigma_mm": 0.02,                   the instrument's noise per axis (the floor is √3 σ)
 *   "expected": {
 *     "verdict": "named",               named | outside | null
 *     "claims": [ { "family": "lost-motion", "joints": [2] } ]    (named only; joints 1-based)
 *   },
 *   "scenario": "any name",             optional: runs of one name share a table row (default: NAME)
 *   "family": "any group",              optional (default: held-out)
 *   "outlier_poses": ["17", "83"],      optional: poses made grossly wrong on purpose
 *   "seed": 7,                          optional
 *   "twin": "NAME.twin.csv"             optional: the campaign's geometry-only twin (same poses, order and noise
 *                                       draws, nothing concealed, no outlier), a file beside the label
 * }
 * </pre>
 * A claim's family is one of transmission-error, lost-motion, gravity-elasticity, thermal-growth,
 * gear-ratio, cross-coupling (or the diagnosis name of one, e.g. backlash); a cross-coupling's
 * joints are the driven joint, then the source. The world simulator's own truth record
 * ({@link #write}) is such a label with more fields, which are ignored.
 */
public final class ScenarioFiles {
    private ScenarioFiles() { }

    /** The label file's name ending, beside NAME.csv. */
    public static final String LABEL = ".truth.json";

    /** The name ending of a twin campaign written by {@link #write}; such files are twins, not campaigns of their own. */
    public static final String TWIN = ".twin.csv";

    /** Every {@code *.csv} of {@code dir} (in name order) with its label, read and checked; none is left out silently. */
    public static List<DiagnosisBenchmark.Case> read(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) throw new InputException(dir.toString(), 0, 0, null, "is not a directory of campaign files");
        List<Path> csvs;
        try (Stream<Path> s = Files.list(dir)) {
            csvs = s.filter(p -> p.getFileName().toString().endsWith(".csv") && !p.getFileName().toString().endsWith(TWIN)
                    && Files.isRegularFile(p)).sorted().toList();
        }
        if (csvs.isEmpty()) throw new InputException(dir.toString(), 0, 0, null, "holds no campaign file (NAME.csv with NAME" + LABEL + ")");
        List<DiagnosisBenchmark.Case> out = new ArrayList<>();
        for (Path csv : csvs) out.add(readCase(csv));
        return out;
    }

    /** One campaign file and the label beside it. */
    public static DiagnosisBenchmark.Case readCase(Path csv) throws IOException {
        String file = csv.getFileName().toString();
        String stem = file.substring(0, file.length() - ".csv".length());
        Path labelPath = csv.resolveSibling(stem + LABEL);
        if (!Files.isRegularFile(labelPath))
            throw new InputException(csv.toString(), 0, 0, null, "no truth label beside it: expected " + labelPath.getFileName());
        String where = labelPath.toString();
        JsonNode root;
        try {
            root = JsonMapper.create().readTree(Files.readString(labelPath));
        } catch (JsonProcessingException e) {
            throw new InputException(where, e.getLocation() == null ? 0 : e.getLocation().getLineNr(),
                    e.getLocation() == null ? 0 : e.getLocation().getColumnNr(), null, "not JSON: " + e.getOriginalMessage());
        }
        if (root == null || !root.isObject()) throw new InputException(where, 0, 0, null, "must be a JSON object");
        RobotDescription robot = robot(where, csv.getParent(), text(where, root, "robot"));
        JsonNode sigma = root.get("sigma_mm");
        if (sigma == null || !sigma.isNumber() || !(sigma.asDouble() > 0) || !Double.isFinite(sigma.asDouble()))
            throw new InputException(where, 0, 0, "sigma_mm", "the instrument's noise per axis in mm, a number > 0, is required");
        Expected expected = expected(where, root.get("expected"), robot.dof());
        Set<String> outliers = new LinkedHashSet<>();
        JsonNode op = root.get("outlier_poses");
        if (op != null && !op.isNull()) {
            if (!op.isArray()) throw new InputException(where, 0, 0, "outlier_poses", "must be a list of pose names");
            op.forEach(n -> outliers.add(n.asText()));
        }
        String name = root.hasNonNull("scenario") ? root.get("scenario").asText() : stem;
        String group = root.hasNonNull("family") ? root.get("family").asText() : "held-out";
        long seed = root.hasNonNull("seed") && root.get("seed").canConvertToLong() ? root.get("seed").asLong() : 0;
        String twin = null;
        if (root.hasNonNull("twin")) {
            Path t = csv.resolveSibling(root.get("twin").asText());
            if (!root.get("twin").isTextual() || !Files.isRegularFile(t))
                throw new InputException(where, 0, 0, "twin", "names no campaign file beside the label: " + root.get("twin"));
            twin = Files.readString(t);
        }
        return new DiagnosisBenchmark.Case(name, group, robot, csv.toString(), Files.readString(csv), expected, sigma.asDouble() * 1e-3,
                outliers, seed, twin);
    }

    private static String text(String where, JsonNode root, String field) {
        JsonNode n = root.get(field);
        if (n == null || !n.isTextual() || n.asText().isBlank()) throw new InputException(where, 0, 0, field, "required (text)");
        return n.asText();
    }

    private static RobotDescription robot(String where, Path dir, String robot) {
        Path f = dir == null ? Path.of(robot) : dir.resolve(robot);
        if (Files.isRegularFile(f)) return RobotLibrary.load(f.toString()); // a bad robot file names itself
        try {
            return RobotLibrary.shipped(robot);
        } catch (RuntimeException e) {
            throw new InputException(where, 0, 0, "robot", "'" + robot + "' is neither a shipped robot nor a robot file beside the label");
        }
    }

    private static Expected expected(String where, JsonNode e, int dof) {
        if (e == null || !e.isObject()) throw new InputException(where, 0, 0, "expected", "required: {\"verdict\": ..., \"claims\": [...]}");
        JsonNode v = e.get("verdict");
        Expected.Verdict verdict = null;
        if (v != null && v.isTextual())
            for (Expected.Verdict x : Expected.Verdict.values()) if (x.name().equalsIgnoreCase(v.asText().strip())) verdict = x;
        if (verdict == null) throw new InputException(where, 0, 0, "expected.verdict", "must be named, outside or null");
        List<Expected.Claim> claims = new ArrayList<>();
        JsonNode cs = e.get("claims");
        if (cs != null && !cs.isNull()) {
            if (!cs.isArray()) throw new InputException(where, 0, 0, "expected.claims", "must be a list");
            for (int i = 0; i < cs.size(); i++) {
                String f = "expected.claims[" + i + "]";
                JsonNode c = cs.get(i);
                Expected.Family fam = Expected.Family.parse(c.path("family").asText(null));
                if (fam == null && c.path("diagnosis_names").isArray() && c.path("diagnosis_names").size() > 0)
                    fam = Expected.Family.parse(c.path("diagnosis_names").get(0).asText());
                if (fam == null)
                    throw new InputException(where, 0, 0, f + ".family", "unknown family '" + c.path("family").asText("") + "'; one of "
                            + String.join(", ", java.util.Arrays.stream(Expected.Family.values())
                                    .map(x -> x.name().toLowerCase(Locale.ROOT).replace('_', '-')).toList()));
                List<Integer> joints = new ArrayList<>();
                JsonNode js = c.get("joints");
                if (js != null && js.isArray())
                    for (JsonNode j : js) {
                        if (!j.canConvertToInt() || j.asInt() < 1 || j.asInt() > dof)
                            throw new InputException(where, 0, 0, f + ".joints", "joint numbers run from 1 to " + dof + ", not " + j);
                        joints.add(j.asInt());
                    }
                if (!fam.jointless() && joints.isEmpty()) throw new InputException(where, 0, 0, f + ".joints", "the joints it acts on are required");
                claims.add(new Expected.Claim(fam, joints));
            }
        }
        if ((verdict == Expected.Verdict.NAMED) == claims.isEmpty())
            throw new InputException(where, 0, 0, "expected.claims", verdict == Expected.Verdict.NAMED
                    ? "a named verdict lists what must be named" : "only a named verdict lists claims");
        return new Expected(verdict, claims);
    }

    /**
     * Writes world trials as such a directory: for each scenario and seed (baseSeed + k) the
     * campaign's measurement file, its geometry-only twin ({@code NAME.twin.csv}) and the world's
     * truth record as its label (naming the twin). Refuses (writing nothing) when a file exists and
     * {@code overwrite} is false. Returns the number of campaigns.
     */
    public static int write(List<Scenario> scenarios, int seeds, long baseSeed, Path dir, boolean overwrite) throws IOException {
        List<String> stems = new ArrayList<>();
        for (Scenario s : scenarios) for (int k = 0; k < seeds; k++) stems.add(stem(s.name(), baseSeed + k));
        if (!overwrite)
            for (String st : stems)
                for (String f : List.of(st + ".csv", st + TWIN, st + LABEL))
                    if (Files.exists(dir.resolve(f))) throw new java.nio.file.FileAlreadyExistsException(dir.resolve(f).toString(), null,
                            "exists (use --force to replace)");
        Files.createDirectories(dir);
        int i = 0;
        for (Scenario s : scenarios)
            for (int k = 0; k < seeds; k++) {
                Scenario.Trial t = s.trial(baseSeed + k);
                String st = stems.get(i++);
                AtomicFiles.writeString(dir.resolve(st + ".csv"), t.campaign().text(), true);
                AtomicFiles.writeString(dir.resolve(st + TWIN), s.twin(baseSeed + k).campaign().text(), true);
                var label = (com.fasterxml.jackson.databind.node.ObjectNode) JsonMapper.create().readTree(t.truthJson());
                label.put("twin", st + TWIN);
                AtomicFiles.writeString(dir.resolve(st + LABEL),
                        JsonMapper.create().writerWithDefaultPrettyPrinter().writeValueAsString(label) + "\n", true);
            }
        return stems.size();
    }

    /** A file name for a scenario's run: its name in letters, digits and '-', then the seed. */
    static String stem(String name, long seed) {
        String s = name.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9]+", "-").replaceAll("^-|-$", "");
        return s + "-s" + seed;
    }
}
