package org.robopro.app.benchmark;

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
import org.robopro.models.LocatedJson;
import org.robopro.models.LocatedJson.Kind;
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
        LocatedJson.Node root = LocatedJson.parse(labelPath.toString(), Files.readString(labelPath));
        if (root.kind() != Kind.OBJECT) throw root.error("must be a JSON object");
        RobotDescription robot = robot(csv.getParent(), root);
        LocatedJson.Node sigma = root.opt("sigma_mm");
        double sigmaMm = sigma == null || sigma.kind() != Kind.NUMBER ? Double.NaN : Double.parseDouble(sigma.numberText());
        if (!(sigmaMm > 0) || !Double.isFinite(sigmaMm))
            throw at(root, sigma, "sigma_mm", "the instrument's noise per axis in mm, a number > 0, is required");
        Expected expected = expected(root, robot.dof());
        Set<String> outliers = new LinkedHashSet<>();
        LocatedJson.Node op = root.opt("outlier_poses");
        if (op != null) {
            if (op.kind() != Kind.ARRAY) throw op.error("must be a list of pose names");
            for (LocatedJson.Node n : op.items()) {
                if (n.kind() == Kind.STRING) outliers.add(n.asString());
                else if (n.kind() == Kind.NUMBER) outliers.add(n.numberText());
                else throw n.error("a pose name (text or number) is required");
            }
        }
        String name = root.has("scenario") ? root.get("scenario").asString() : stem;
        String group = root.has("family") ? root.get("family").asString() : "held-out";
        long seed = root.has("seed") ? seed(root.get("seed")) : 0;
        Path twin = null;
        if (root.has("twin")) {
            LocatedJson.Node tn = root.get("twin");
            twin = csv.resolveSibling(tn.asString());
            if (!Files.isRegularFile(twin)) throw tn.error("names no campaign file beside the label: \"" + tn.asString() + "\"");
        }
        DiagnosisBenchmark.Case c = new DiagnosisBenchmark.Case(name, group, robot, csv.toString(), Files.readString(csv), expected, sigmaMm * 1e-3,
                outliers, seed, twin == null ? null : Files.readString(twin), twin == null ? null : twin.toString());
        // Both measurement files read now, so that a bad one stops the benchmark before anything is diagnosed.
        DiagnosisBenchmark.read(c);
        if (twin != null) DiagnosisBenchmark.read(c.twin());
        return c;
    }

    /** The error for {@code field} of {@code obj}: at the value when it is given, else at the object. */
    private static InputException at(LocatedJson.Node obj, LocatedJson.Node value, String field, String problem) {
        if (value != null) return value.error(problem);
        return new InputException(obj.file(), obj.line(), obj.column(), obj.path().isEmpty() ? field : obj.path() + "." + field, problem);
    }

    private static String text(LocatedJson.Node root, String field) {
        LocatedJson.Node n = root.opt(field);
        if (n == null || n.kind() != Kind.STRING || n.asString().isBlank()) throw at(root, n, field, "required (text)");
        return n.asString();
    }

    private static long seed(LocatedJson.Node n) {
        try {
            return n.asDecimal().longValueExact();
        } catch (ArithmeticException e) {
            throw n.error("the seed must be a whole number, got " + n.numberText());
        }
    }

    private static RobotDescription robot(Path dir, LocatedJson.Node root) {
        String robot = text(root, "robot");
        Path f = dir == null ? Path.of(robot) : dir.resolve(robot);
        if (Files.isRegularFile(f)) return RobotLibrary.load(f.toString()); // a bad robot file names itself
        try {
            return RobotLibrary.shipped(robot);
        } catch (RuntimeException e) {
            throw root.get("robot").error("'" + robot + "' is neither a shipped robot nor a robot file beside the label");
        }
    }

    /** A joint number of a claim: a whole number from 1 to {@code dof}. */
    private static boolean isJoint(LocatedJson.Node j, int dof) {
        if (j.kind() != Kind.NUMBER) return false;
        double d = Double.parseDouble(j.numberText());
        return d == Math.rint(d) && d >= 1 && d <= dof;
    }

    /** A scalar value as it is written in the file (text quoted), for messages. */
    private static String shown(LocatedJson.Node n) {
        return switch (n.kind()) {
            case STRING -> "\"" + n.asString() + "\"";
            case NUMBER -> n.numberText();
            case BOOLEAN -> String.valueOf(n.asBoolean());
            case NULL -> "null";
            case OBJECT -> "an object";
            case ARRAY -> "a list";
        };
    }

    private static Expected expected(LocatedJson.Node root, int dof) {
        LocatedJson.Node e = root.opt("expected");
        if (e == null || e.kind() != Kind.OBJECT) throw at(root, e, "expected", "required: {\"verdict\": ..., \"claims\": [...]}");
        LocatedJson.Node v = e.opt("verdict");
        Expected.Verdict verdict = null;
        if (v != null && v.kind() == Kind.STRING)
            for (Expected.Verdict x : Expected.Verdict.values()) if (x.name().equalsIgnoreCase(v.asString().strip())) verdict = x;
        if (verdict == null) throw at(e, v, "verdict", "must be named, outside or null");
        List<Expected.Claim> claims = new ArrayList<>();
        LocatedJson.Node cs = e.opt("claims");
        if (cs != null) {
            if (cs.kind() != Kind.ARRAY) throw cs.error("must be a list");
            for (LocatedJson.Node c : cs.items()) {
                if (c.kind() != Kind.OBJECT) throw c.error("a claim must be an object: {\"family\": ..., \"joints\": [...]}");
                LocatedJson.Node fn = c.opt("family");
                Expected.Family fam = fn != null && fn.kind() == Kind.STRING ? Expected.Family.parse(fn.asString()) : null;
                LocatedJson.Node dn = c.opt("diagnosis_names");
                if (fam == null && dn != null && dn.kind() == Kind.ARRAY && !dn.items().isEmpty() && dn.items().get(0).kind() == Kind.STRING)
                    fam = Expected.Family.parse(dn.items().get(0).asString());
                if (fam == null)
                    throw at(c, fn, "family", "unknown family '" + (fn == null ? "" : fn.kind() == Kind.STRING ? fn.asString() : shown(fn)) + "'; one of "
                            + String.join(", ", java.util.Arrays.stream(Expected.Family.values())
                                    .map(x -> x.name().toLowerCase(Locale.ROOT).replace('_', '-')).toList()));
                List<Integer> joints = new ArrayList<>();
                LocatedJson.Node js = c.opt("joints");
                if (js != null) {
                    if (js.kind() != Kind.ARRAY) throw js.error("must be a list of joint numbers");
                    for (LocatedJson.Node j : js.items()) {
                        if (!isJoint(j, dof))
                            throw new InputException(j.file(), j.line(), j.column(), js.path(), "joint numbers run from 1 to " + dof + ", not " + shown(j));
                        joints.add(j.asInt());
                    }
                }
                if (!fam.jointless() && joints.isEmpty()) throw at(c, js, "joints", "the joints it acts on are required");
                claims.add(new Expected.Claim(fam, joints));
            }
        }
        if ((verdict == Expected.Verdict.NAMED) == claims.isEmpty())
            throw at(e, cs, "claims", verdict == Expected.Verdict.NAMED
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
