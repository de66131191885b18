package org.robopro.models;

import com.fasterxml.jackson.core.io.JsonStringEncoder;
import java.util.List;

/**
 * A small pretty-printer for robopro's files: objects one member per line, short numeric arrays
 * on one line ({@code "point": [0, 0, 780]}), numbers as given (already formatted by
 * {@link FileNumbers}). Hand-rolled because the numbers must be written exactly as chosen.
 */
final class JsonOut {
    private final StringBuilder sb = new StringBuilder();
    private int depth;
    private boolean first = true;

    JsonOut beginObject(String key) {
        member(key);
        sb.append('{');
        depth++;
        first = true;
        return this;
    }

    JsonOut endObject() {
        depth--;
        if (!first) newline();
        sb.append('}');
        first = false;
        return this;
    }

    JsonOut beginArray(String key) {
        member(key);
        sb.append('[');
        depth++;
        first = true;
        return this;
    }

    JsonOut endArray() {
        depth--;
        if (!first) newline();
        sb.append(']');
        first = false;
        return this;
    }

    JsonOut string(String key, String value) {
        member(key);
        quote(value);
        return this;
    }

    /** A number already formatted as JSON number text. */
    JsonOut number(String key, String text) {
        member(key);
        sb.append(text);
        return this;
    }

    JsonOut bool(String key, boolean value) {
        member(key);
        sb.append(value);
        return this;
    }

    /** An inline array of formatted numbers. */
    JsonOut numbers(String key, String... texts) {
        member(key);
        sb.append('[').append(String.join(", ", texts)).append(']');
        return this;
    }

    /** An inline array of strings. */
    JsonOut strings(String key, List<String> values) {
        member(key);
        sb.append('[');
        for (int i = 0; i < values.size(); i++) {
            if (i > 0) sb.append(", ");
            quote(values.get(i));
        }
        sb.append(']');
        return this;
    }

    /** key null: an array element. */
    private void member(String key) {
        if (depth > 0) {
            if (!first) sb.append(',');
            newline();
        }
        first = false;
        if (key != null) {
            quote(key);
            sb.append(": ");
        }
    }

    private void newline() {
        sb.append('\n');
        for (int i = 0; i < depth; i++) sb.append("  ");
    }

    private void quote(String s) {
        sb.append('"');
        sb.append(JsonStringEncoder.getInstance().quoteAsString(s));
        sb.append('"');
    }

    @Override
    public String toString() { return sb.toString() + "\n"; }
}
