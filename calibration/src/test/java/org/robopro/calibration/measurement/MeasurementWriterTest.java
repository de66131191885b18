package org.robopro.calibration.measurement;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.models.JointType;
import org.robopro.models.Vec3;

class MeasurementWriterTest {
    @TempDir Path dir;

    static MeasurementSet randomSet(long seed, boolean sixD) {
        Random r = new Random(seed);
        List<Measurement> rows = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            double[] q = new double[6];
            for (int k = 0; k < 6; k++) q[k] = (r.nextDouble() - 0.5) * 4;
            Vec3 p = new Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
            double[] o = null;
            if (sixD) {
                o = new double[] {r.nextGaussian(), r.nextGaussian(), r.nextGaussian(), r.nextGaussian()};
                double n = Math.sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3]);
                for (int k = 0; k < 4; k++) o[k] /= n;
            }
            int[] d = new int[6];
            for (int k = 0; k < 6; k++) d[k] = r.nextInt(3) - 1;
            rows.add(new Measurement("p" + i, q, p, o, d, i * 10.5, 20 + r.nextDouble(), 2.5,
                    i % 4 == 0 ? Measurement.Split.VALIDATE : Measurement.Split.TRAIN, 0));
        }
        Map<String, String> meta = new LinkedHashMap<>();
        meta.put("robot", "irb2000");
        meta.put("instrument", "simulated");
        return new MeasurementSet("mem", meta, "tracker", rows);
    }

    @Test
    void writeThenRead_everyColumn_roundTripsWithinPrintedPrecision() throws Exception {
        MeasurementSet s = randomSet(3, true);
        Path f = dir.resolve("m.csv");
        List<JointType> types = List.of(JointType.REVOLUTE, JointType.REVOLUTE, JointType.PRISMATIC,
                JointType.REVOLUTE, JointType.REVOLUTE, JointType.REVOLUTE);
        MeasurementWriter.write(s, types, f, false);
        MeasurementSet back = MeasurementReader.read(f, types);
        assertEquals(s.size(), back.size());
        assertEquals("tracker", back.frame());
        assertEquals("irb2000", back.robot());
        for (int i = 0; i < s.size(); i++) {
            Measurement a = s.rows().get(i), b = back.rows().get(i);
            assertEquals(a.poseId(), b.poseId());
            for (int k = 0; k < 6; k++) assertEquals(a.q(k), b.q(k), 1e-10);
            assertEquals(0, a.position().minus(b.position()).norm(), 2e-9);
            assertArrayEquals(a.orientation(), b.orientation(), 1e-11);
            assertArrayEquals(a.directions(), b.directions());
            assertEquals(a.timeS(), b.timeS(), 1e-9);
            assertEquals(a.tempC(), b.tempC(), 1e-3);
            assertEquals(a.set(), b.set());
        }
    }

    @Test
    void write_existingFile_isRefusedUnlessAsked() throws Exception {
        Path f = dir.resolve("m.csv");
        Files.writeString(f, "precious");
        MeasurementSet s = randomSet(4, false);
        assertThrows(FileAlreadyExistsException.class, () -> MeasurementWriter.write(s, null, f, false));
        assertEquals("precious", Files.readString(f));
        MeasurementWriter.write(s, null, f, true);
        assertEquals(20, MeasurementReader.read(f, (List<JointType>) null).size());
    }
}
