package org.robopro.models;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import java.io.IOException;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A JSON tree that remembers, for every value, the file, line, column and field path it came from,
 * so that readers of robopro's files (robot, cell, ...) can refuse bad input with an
 * {@link InputException} that points at the offending field. Jackson's own tree model drops
 * locations, hence this small tree built from Jackson's streaming parser.
 *
 * <p>Accepts {@code //} and {@code /* *}{@code /} comments (robopro files are edited by hand);
 * refuses duplicate keys, trailing content and non-finite numbers. Numbers keep their decimal text
 * so that unit conversions can be done exactly (see {@link FileNumbers}).
 */
public final class LocatedJson {
    private static final JsonFactory FACTORY = JsonFactory.builder()
            .enable(JsonReadFeature.ALLOW_JAVA_COMMENTS)
            .streamReadConstraints(StreamReadConstraints.builder()
                    .maxNestingDepth(200).maxNumberLength(200).maxStringLength(10_000_000).build())
            .build();

    private LocatedJson() { }

    public enum Kind { OBJECT, ARRAY, STRING, NUMBER, BOOLEAN, NULL }

    /** One value with its location; {@code path} is the field path ("joints[2].axis"). */
    public static final class Node {
        private final String file;
        private final String key;                   // member name, null for array items and the root
        private final String path;
        private final int line;
        private final int column;
        private final Kind kind;
        private final String text;                  // STRING value, NUMBER text, BOOLEAN text
        private final Map<String, Node> members;    // OBJECT
        private final List<Node> items;             // ARRAY

        private Node(String file, String key, String path, int line, int column, Kind kind, String text,
                     Map<String, Node> members, List<Node> items) {
            this.file = file;
            this.key = key;
            this.path = path;
            this.line = line;
            this.column = column;
            this.kind = kind;
            this.text = text;
            this.members = members;
            this.items = items;
        }

        public String file() { return file; }
        public String path() { return path; }
        /** Member name of this value in its object, null for array items and the root. */
        public String key() { return key; }
        public int line() { return line; }
        public int column() { return column; }
        public Kind kind() { return kind; }

        /** An {@link InputException} located at this value. */
        public InputException error(String problem) {
            return new InputException(file, line, column, path, problem);
        }

        private String child(String key) { return path.isEmpty() ? key : path + "." + key; }

        // ---- objects

        public Map<String, Node> members() {
            expect(Kind.OBJECT);
            return members;
        }

        /** Refuses any member not in {@code allowed} (catches misspelt field names). */
        public Node onlyFields(Set<String> allowed) {
            for (Node n : members().values()) {
                if (!allowed.contains(n.key))
                    throw n.error("unknown field; expected one of " + new java.util.TreeSet<>(allowed));
            }
            return this;
        }

        public boolean has(String key) { return members().containsKey(key) && members.get(key).kind != Kind.NULL; }

        /** The member {@code key}; an error at this object if it is missing or null. */
        public Node get(String key) {
            Node n = members().get(key);
            if (n == null || n.kind == Kind.NULL)
                throw new InputException(file, line, column, child(key), "missing required field");
            return n;
        }

        /** The member {@code key}, or null if absent or null. */
        public Node opt(String key) {
            Node n = members().get(key);
            return n == null || n.kind == Kind.NULL ? null : n;
        }

        // ---- arrays

        public List<Node> items() {
            expect(Kind.ARRAY);
            return items;
        }

        public List<Node> items(int size) {
            List<Node> l = items();
            if (l.size() != size) throw error("expected " + size + " values, got " + l.size());
            return l;
        }

        // ---- scalars

        public String asString() {
            expect(Kind.STRING);
            return text;
        }

        public String asNonEmptyString() {
            String s = asString();
            if (s.isBlank()) throw error("must not be empty");
            return s;
        }

        public boolean asBoolean() {
            expect(Kind.BOOLEAN);
            return Boolean.parseBoolean(text);
        }

        /** The number's exact decimal value. */
        public BigDecimal asDecimal() {
            expect(Kind.NUMBER);
            return new BigDecimal(text);
        }

        /** True for a number written with a leading minus sign (keeps -0 apart from 0). */
        public boolean isNegativeText() {
            expect(Kind.NUMBER);
            return text.startsWith("-");
        }

        /** The number as a double; refuses values that overflow to infinity. */
        public double asDouble() {
            expect(Kind.NUMBER);
            double d = Double.parseDouble(text);
            if (!Double.isFinite(d)) throw error("number out of range: " + text);
            return d;
        }

        public int asInt() {
            double d = asDouble();
            if (d != Math.rint(d) || Math.abs(d) > 1e9) throw error("expected an integer, got " + text);
            return (int) d;
        }

        public String numberText() {
            expect(Kind.NUMBER);
            return text;
        }

        private void expect(Kind k) {
            if (kind != k) throw error("expected " + article(k) + ", got " + article(kind));
        }

        private static String article(Kind k) {
            return switch (k) {
                case OBJECT -> "an object";
                case ARRAY -> "an array";
                case STRING -> "a string";
                case NUMBER -> "a number";
                case BOOLEAN -> "true/false";
                case NULL -> "null";
            };
        }
    }

    /** Parses {@code text} (named {@code file} in errors) into a located tree. */
    public static Node parse(String file, String text) {
        try (JsonParser p = FACTORY.createParser(text)) {
            JsonToken t = p.nextToken();
            if (t == null) throw new InputException(file, 1, 1, null, "empty file");
            Node root = read(p, t, file, null, "");
            JsonToken extra;
            try {
                extra = p.nextToken();
            } catch (JsonProcessingException e) {
                throw located(file, e);
            }
            if (extra != null) {
                JsonLocation l = p.currentTokenLocation();
                throw new InputException(file, l.getLineNr(), l.getColumnNr(), null,
                        "unexpected content after the end of the document");
            }
            return root;
        } catch (JsonProcessingException e) {
            throw located(file, e);
        } catch (IOException e) {
            throw new InputException(file, 0, 0, null, "cannot read: " + e.getMessage(), e);
        }
    }

    private static InputException located(String file, JsonProcessingException e) {
        JsonLocation l = e.getLocation();
        String msg = e.getOriginalMessage();
        if (msg == null) msg = e.getClass().getSimpleName();
        int nl = msg.indexOf('\n');
        if (nl > 0) msg = msg.substring(0, nl);
        return new InputException(file, l == null ? 0 : Math.max(0, l.getLineNr()),
                l == null ? 0 : Math.max(0, l.getColumnNr()), null, "malformed JSON: " + plain(msg), e);
    }

    /** Jackson's parse message in plain words: no parser options to enable, no character codes. */
    static String plain(String msg) {
        String m = msg;
        for (String cut : new String[] {": enable", "; enable", " to allow", " (for Object starting", " (for root starting"}) {
            int i = m.indexOf(cut);
            if (i > 0) m = m.substring(0, i);
        }
        m = m.replaceAll(" \\(code \\d+\\)", "")
             .replaceAll("\\(CTRL-CHAR, code \\d+\\)", "(a control character)")
             .replace("(JSON String, Number, Array, Object or token 'null', 'true' or 'false')", "(a JSON value)")
             .replace("Non-standard token", "not a JSON value:")
             .replace("Unrecognized token", "unrecognized word")
             .replace("Unexpected character", "unexpected character")
             .replace("Unexpected end-of-input", "the file ends too early")
             .replace("expected double-quote to start field name", "a field name must be in double quotes");
        if (m.contains("'NaN'") || m.contains("'Infinity'") || m.contains("'-Infinity'"))
            m = m + " (JSON has no NaN or infinity; write a finite number or null)";
        return m.strip();
    }

    private static Node read(JsonParser p, JsonToken t, String file, String key, String path) throws IOException {
        JsonLocation loc = p.currentTokenLocation();
        int line = loc.getLineNr(), col = loc.getColumnNr();
        switch (t) {
            case START_OBJECT: {
                Map<String, Node> m = new LinkedHashMap<>();
                while ((t = p.nextToken()) == JsonToken.FIELD_NAME) {
                    String name = p.currentName();
                    JsonLocation kl = p.currentTokenLocation();
                    String childPath = path.isEmpty() ? name : path + "." + name;
                    if (m.containsKey(name))
                        throw new InputException(file, kl.getLineNr(), kl.getColumnNr(), childPath,
                                "duplicate field (first given on line " + m.get(name).line + ")");
                    m.put(name, read(p, p.nextToken(), file, name, childPath));
                }
                return new Node(file, key, path, line, col, Kind.OBJECT, null, Collections.unmodifiableMap(m), null);
            }
            case START_ARRAY: {
                List<Node> l = new ArrayList<>();
                while ((t = p.nextToken()) != JsonToken.END_ARRAY)
                    l.add(read(p, t, file, null, path + "[" + l.size() + "]"));
                return new Node(file, key, path, line, col, Kind.ARRAY, null, null, Collections.unmodifiableList(l));
            }
            case VALUE_STRING:
                return new Node(file, key, path, line, col, Kind.STRING, p.getText(), null, null);
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT:
                return new Node(file, key, path, line, col, Kind.NUMBER, p.getText(), null, null);
            case VALUE_TRUE:
            case VALUE_FALSE:
                return new Node(file, key, path, line, col, Kind.BOOLEAN, p.getText(), null, null);
            case VALUE_NULL:
                return new Node(file, key, path, line, col, Kind.NULL, null, null, null);
            default:
                throw new InputException(file, line, col, path, "unexpected JSON token " + t);
        }
    }
}
