package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.List;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.EffectDescription;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;

/**
 * A robot model with its non-geometric effects: the (calibrated) geometry plus identified
 * {@link Effect} terms. Forward kinematics takes the controller values q and the conditions of
 * the motion (approach directions, temperature, payload, time): the drive effects are added to
 * q (before the coupling θ = C q), every length is stretched by the thermal strain about the base
 * origin, and the effects on the measured point are added. Written to and read from the robot
 * file's {@code effects} section. Immutable and thread-safe.
 */
public final class ExtendedModel {
    private final KinematicModel geometry;
    private final List<Effect.Term> terms;

    public ExtendedModel(KinematicModel geometry, List<Effect.Term> terms) {
        this.geometry = geometry;
        this.terms = List.copyOf(terms);
    }

    /**
     * The extended model of a robot file: its geometry and its {@code effects} (none: a purely
     * geometric model). {@code file} names the source in error messages.
     */
    public static ExtendedModel of(RobotDescription robot, String file) {
        KinematicModel m = KinematicModel.build(robot);
        GravityTorques g = GravityTorques.of(m, robot);
        List<Effect.Term> ts = new ArrayList<>();
        for (EffectDescription d : robot.effects()) ts.add(Effect.fromDescription(d, m, g, file));
        return new ExtendedModel(m, ts);
    }

    public KinematicModel geometry() { return geometry; }
    public List<Effect.Term> terms() { return terms; }
    public boolean hasEffects() { return !terms.isEmpty(); }

    /** The drive outputs the geometry really sees at controller values q under conditions c (before the coupling). */
    public double[] effectiveQ(double[] q, PoseConditions c) {
        double[] out = q.clone();
        for (Effect.Term t : terms)
            if (t.effect().target() == Effect.Target.DRIVE) t.effect().addToDrives(t.effect().value(t.values(), q, c), out);
        return out;
    }

    /** Relative length change at conditions c. */
    public double strain(PoseConditions c) {
        double s = 0;
        for (Effect.Term t : terms) if (t.effect().isStrain()) s += t.effect().value(t.values(), null, c);
        return s;
    }

    /** baseTflange at q under conditions c. */
    public Pose flange(double[] q, PoseConditions c) {
        return tool(q, Pose.IDENTITY, c);
    }

    /**
     * baseTtool at q under conditions c: the geometry at the drive outputs, every length stretched
     * by the thermal strain about the base origin (the tool point too), then the effects on the
     * measured point added (link growth, drift).
     */
    public Pose tool(double[] q, Pose flangeTtool, PoseConditions c) {
        Pose t = geometry.flange(effectiveQ(q, c)).times(flangeTtool);
        double s = strain(c);
        Vec3 d = t.position().times(s);
        Vec3 p = t.position();
        Vec3 w = Vec3.ZERO;
        for (Effect.Term term : terms)
            // an error of the measuring instrument's readings is not where the robot is: it moves no tool
            if (term.effect().target() == Effect.Target.POSITION && !term.effect().ofInstrument()) {
                d = d.plus(term.effect().displacement(term.values(), q, c, p));
                if (term.effect().turnsFrame()) w = w.plus(term.effect().rotation(term.values(), q, c));
            }
        if (w.norm() > 0) {
            // the tool's frame turned in base coordinates about its own point (the point's move is in d)
            double[] r = new double[9], turned = new double[9];
            org.robopro.kinematics.Se3.rotExp(w.x(), w.y(), w.z(), r);
            org.robopro.kinematics.Se3.rotMul(r, t.rotationRowMajor(), turned);
            t = Pose.of(turned, t.x(), t.y(), t.z());
        }
        return d.norm() == 0 ? t : Pose.translation(d).times(t);
    }

    /** The robot file form: the geometry's description with the effects section filled in. */
    public RobotDescription toDescription() {
        List<EffectDescription> ds = new ArrayList<>();
        for (Effect.Term t : terms) ds.add(t.effect().describe(t.values()));
        return geometry.toDescription().withEffects(ds);
    }
}
