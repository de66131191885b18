package org.robopro.comms.client;

import java.util.Random;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.Commands;
import org.robopro.comms.TrackerReading;
import org.robopro.comms.sim.SimulatedController;
import org.robopro.comms.sim.TestSupport;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;

/**
 * A soak through a faulty link that checks every value, not only that commands ran: each cycle
 * moves to random joints, reads them back and measures, one command at a time. A value counts
 * as corrupted when the controller executed other joints than were sent (the request was
 * damaged), or when the joints or the measurement read back differ from what the controller
 * holds (the reply was damaged). The expected values come from the simulator itself, read
 * directly (not over the link).
 */
final class LinkSoak {
    record Figures(int commands, int moves, int failed, int lost, int duplicated, int corrupted, double seconds) {
        @Override
        public String toString() {
            return String.format(java.util.Locale.ROOT, "%d commands (%d motions) in %.1f s: failed %d, lost %d, duplicated %d, corrupted %d",
                    commands, moves, seconds, failed, lost, duplicated, corrupted);
        }
    }

    private LinkSoak() { }

    /** Degrees as the wire carries them (4 decimals), back in radians. */
    private static double wire(double rad) {
        return Units.degToRad(Double.parseDouble(org.robopro.comms.protocol.OpenAbb.num(Units.radToDeg(rad), 4)));
    }

    private static String mm(Vec3 p) {
        return org.robopro.comms.protocol.OpenAbb.num(Units.mToMm(p.x()), 4) + " " + org.robopro.comms.protocol.OpenAbb.num(Units.mToMm(p.y()), 4)
                + " " + org.robopro.comms.protocol.OpenAbb.num(Units.mToMm(p.z()), 4);
    }

    static Figures run(CommandInvoker inv, SimulatedController sim, int commands, long seed) {
        Random rnd = new Random(seed);
        int n = 0, moves = 0, failed = 0, lost = 0, duplicated = 0, corrupted = 0;
        long t0 = System.nanoTime();
        while (n < commands) {
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) q[j] = rnd.nextDouble() - 0.5;
            Commands.MoveJoints m = Commands.moveJoints(q);
            try {
                inv.execute(m);
                moves++;
            } catch (RuntimeException e) {
                failed++;
            }
            n++;
            int k = sim.executions(m.requestId());
            if (k == 0) lost++;
            if (k > 1) duplicated++;
            double[] held = sim.readJoints();
            for (int j = 0; j < 6; j++) if (Math.abs(held[j] - wire(q[j])) > 1e-9) { corrupted++; break; }
            try {
                double[] back = inv.execute(Commands.readJoints());
                for (int j = 0; j < 6; j++) if (Math.abs(back[j] - wire(held[j])) > 1e-9) { corrupted++; break; }
            } catch (RuntimeException e) {
                failed++;
            }
            n++;
            try {
                TrackerReading r = inv.execute(Commands.measureReading());
                Vec3 truth = TestSupport.gantryTruePoint(sim);
                // The wire carries 4 decimals of mm: compare what was sent with what arrived, digit for digit.
                if (!mm(r.position()).equals(mm(truth))) corrupted++;
            } catch (RuntimeException e) {
                failed++;
            }
            n++;
        }
        return new Figures(n, moves, failed, lost, duplicated, corrupted, (System.nanoTime() - t0) * 1e-9);
    }
}
