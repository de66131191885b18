package org.robopro.calibration.measurement;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * The contents of a measurement file (docs/measurement-file.md), SI units inside. Immutable.
 *
 * @param source     where the data came from (file name), for messages
 * @param metadata   every {@code # key: value} line in order (keys lower-case), unknown keys included
 * @param frame      the frame the positions are expressed in; "base" means the robot base frame
 * @param rows       the measured poses, in file order
 */
public record MeasurementSet(String source, Map<String, String> metadata, String frame, List<Measurement> rows) {
    public static final String BASE_FRAME = "base";

    public MeasurementSet {
        metadata = Collections.unmodifiableMap(new LinkedHashMap<>(metadata));
        rows = List.copyOf(rows);
        if (frame == null || frame.isBlank()) frame = "instrument";
    }

    /** Positions are in the robot base frame: no instrument frame to identify. */
    public boolean inBaseFrame() { return BASE_FRAME.equalsIgnoreCase(frame.trim()); }

    /** The robot named in the file's metadata, or null. */
    public String robot() { return metadata.get("robot"); }

    public int size() { return rows.size(); }

    public int dof() { return rows.isEmpty() ? 0 : rows.get(0).dof(); }

    /** True when every row carries an orientation (6-D data). */
    public boolean hasOrientation() { return !rows.isEmpty() && rows.stream().allMatch(Measurement::hasOrientation); }

    public boolean hasDirections() { return !rows.isEmpty() && rows.stream().allMatch(m -> m.directions() != null); }
    public boolean hasTime() { return !rows.isEmpty() && rows.stream().allMatch(m -> !Double.isNaN(m.timeS())); }
    public boolean hasTemperature() { return !rows.isEmpty() && rows.stream().allMatch(m -> !Double.isNaN(m.tempC())); }
    public boolean hasPayload() { return !rows.isEmpty() && rows.stream().allMatch(m -> !Double.isNaN(m.payloadKg())); }
    public boolean hasSplit() { return !rows.isEmpty() && rows.stream().allMatch(m -> m.set() != null); }

    /** The rows that satisfy {@code keep}, same metadata. */
    public MeasurementSet filter(Predicate<Measurement> keep) {
        List<Measurement> out = new ArrayList<>();
        for (Measurement m : rows) if (keep.test(m)) out.add(m);
        return new MeasurementSet(source, metadata, frame, out);
    }

    /** Rows of the given split (rows without a {@code set} value count as training data). */
    public MeasurementSet split(Measurement.Split s) {
        return filter(m -> (m.set() == null ? Measurement.Split.TRAIN : m.set()) == s);
    }

    public MeasurementSet withRows(List<Measurement> newRows) {
        return new MeasurementSet(source, metadata, frame, newRows);
    }
}
