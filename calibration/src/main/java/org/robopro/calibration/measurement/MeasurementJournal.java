package org.robopro.calibration.measurement;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Map;
import org.robopro.models.JointType;

/**
 * A measurement file written one row at a time as the measurements arrive, each row appended
 * and synced to disk before the next pose is measured, so a dropped link, a crash or kill -9
 * keeps every pose measured so far. The journal is itself a measurement file (the header is
 * written with the first row; its optional columns are the first row's), readable by
 * {@link MeasurementReader}; a row cut short by a kill is dropped when the journal is resumed.
 * {@link #finish} moves it into place as the final file.
 */
public final class MeasurementJournal implements Closeable {
    private final Path file;
    private final FileChannel ch;
    private final Map<String, String> metadata;
    private final String frame;
    private final int dof;
    private final List<JointType> types;
    private MeasurementWriter.Columns columns;
    private int rows;

    private MeasurementJournal(Path file, FileChannel ch, Map<String, String> metadata, String frame, int dof,
                               List<JointType> types, MeasurementWriter.Columns columns, int rows) {
        this.file = file;
        this.ch = ch;
        this.metadata = metadata;
        this.frame = frame;
        this.dof = dof;
        this.types = types;
        this.columns = columns;
        this.rows = rows;
    }

    /** Starts a new journal; an existing file is refused (it may hold an interrupted campaign). */
    public static MeasurementJournal create(Path file, Map<String, String> metadata, String frame, int dof,
                                            List<JointType> jointTypes) throws IOException {
        if (Files.exists(file)) throw new FileAlreadyExistsException(file.toString(), null, "exists");
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) Files.createDirectories(parent);
        FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        return new MeasurementJournal(file, ch, Map.copyOf(metadata), frame, dof, jointTypes, null, 0);
    }

    /** What a journal on disk holds: its complete rows (null when it has none yet). */
    public static MeasurementSet recover(Path file, List<JointType> jointTypes) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        String complete = completePart(text);
        if (complete.lines().noneMatch(l -> !l.isBlank() && !l.startsWith("#") && !l.startsWith("pose"))) return null;
        return MeasurementReader.parse(file.toString(), complete, jointTypes);
    }

    /**
     * Continues a journal: drops a row cut short by a kill, then appends after the complete rows.
     * {@code done} is what {@link #recover} returned for it (null: start it again from the header).
     */
    public static MeasurementJournal resume(Path file, MeasurementSet done, List<JointType> jointTypes) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        long keep = done == null ? 0 : completePart(text).getBytes(StandardCharsets.UTF_8).length;
        FileChannel ch = FileChannel.open(file, StandardOpenOption.WRITE);
        ch.truncate(keep);
        ch.position(keep);
        ch.force(true);
        if (done == null) {
            return new MeasurementJournal(file, ch, Map.of(), "instrument", -1, jointTypes, null, 0);
        }
        return new MeasurementJournal(file, ch, done.metadata(), done.frame(), done.dof(), jointTypes,
                MeasurementWriter.Columns.of(done), done.size());
    }

    /** Sets the metadata of a resumed journal that had no rows (its header is written again). */
    public MeasurementJournal withHeader(Map<String, String> metadata, String frame, int dof) {
        if (rows > 0) return this;
        return new MeasurementJournal(file, ch, Map.copyOf(metadata), frame, dof, types, null, 0);
    }

    /** The text up to and including the last newline: a row cut short by a kill is not part of it. */
    private static String completePart(String text) {
        int nl = text.lastIndexOf('\n');
        return nl < 0 ? "" : text.substring(0, nl + 1);
    }

    public Path file() { return file; }

    /** Rows in the journal so far. */
    public int rows() { return rows; }

    /** Appends one row and syncs it to disk before returning. */
    public void append(Measurement m) throws IOException {
        StringBuilder sb = new StringBuilder();
        if (columns == null) {
            columns = MeasurementWriter.Columns.of(m);
            MeasurementWriter.header(sb, metadata, frame, dof, columns);
        } else if (!columns.equals(MeasurementWriter.Columns.of(m))) {
            throw new IllegalArgumentException("pose " + m.poseId() + " has other columns than the poses before it");
        }
        MeasurementWriter.row(sb, m, dof, types, columns);
        ByteBuffer b = ByteBuffer.wrap(sb.toString().getBytes(StandardCharsets.UTF_8));
        while (b.hasRemaining()) ch.write(b);
        ch.force(false);
        rows++;
    }

    /** Closes the journal and renames it to {@code target}; {@code overwrite} false refuses an existing file. */
    public void finish(Path target, boolean overwrite) throws IOException {
        close();
        if (!overwrite && Files.exists(target))
            throw new FileAlreadyExistsException(target.toString(), null, "exists; refusing to overwrite it");
        Files.move(file, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    @Override
    public void close() throws IOException {
        if (ch.isOpen()) ch.close();
    }
}
