package org.robopro.programs.rapid;

import java.util.List;

/** The text of an exported module and every name the export had to change. */
public record RapidExport(String text, List<Rename> renames) {
    public RapidExport {
        renames = List.copyOf(renames);
    }

    /** {@code from} was written as {@code to} because of {@code reason}. */
    public record Rename(String kind, String from, String to, String reason) {
        @Override public String toString() { return kind + " '" + from + "' -> '" + to + "' (" + reason + ")"; }
    }
}
