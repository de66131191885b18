package org.robopro.calibration.simulation;

import java.util.List;
import java.util.Random;
import org.robopro.calibration.JointEffect;
import org.robopro.calibration.PoseConditions;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * A simulated real robot: a kinematic model with the "true" geometry, the tool frame whose origin
 * is the measured point (flangeTtool), the instrument's pose (instrumentTbase; identity when the
 * instrument measures in the base frame), measurement noise, and non-geometric effects. The
 * campaign simulator measures it; the simulated controller can drive it. Immutable, thread-safe.
 */
public final class TrueRobot {
    private final KinematicModel model;
    private final Pose flangeTtool;
    private final Pose instrumentTbase;
    private final double sigmaM;
    private final double sigmaRotRad;
    private final List<JointEffect> effects;

    /**
     * @param model           the true geometry
     * @param flangeTtool     the tool frame; its origin is the measured point (target)
     * @param instrumentTbase the robot base seen from the instrument (identity for frame: base)
     * @param sigmaM          position noise, standard deviation per axis, m
     * @param sigmaRotRad     orientation noise, standard deviation per axis, rad
     * @param effects         non-geometric effects, applied in order
     */
    public TrueRobot(KinematicModel model, Pose flangeTtool, Pose instrumentTbase, double sigmaM, double sigmaRotRad,
                     List<JointEffect> effects) {
        if (!(sigmaM >= 0) || !(sigmaRotRad >= 0)) throw new IllegalArgumentException("noise must be >= 0: " + sigmaM + ", " + sigmaRotRad);
        this.model = model;
        this.flangeTtool = flangeTtool;
        this.instrumentTbase = instrumentTbase;
        this.sigmaM = sigmaM;
        this.sigmaRotRad = sigmaRotRad;
        this.effects = List.copyOf(effects);
    }

    public KinematicModel model() { return model; }
    public Pose flangeTtool() { return flangeTtool; }
    public Pose instrumentTbase() { return instrumentTbase; }
    public double sigmaM() { return sigmaM; }
    public double sigmaRotRad() { return sigmaRotRad; }
    public List<JointEffect> effects() { return effects; }

    /** The same robot with other effects (e.g. for a diagnosis benchmark). */
    public TrueRobot withEffects(List<JointEffect> newEffects) {
        return new TrueRobot(model, flangeTtool, instrumentTbase, sigmaM, sigmaRotRad, newEffects);
    }

    /** The joint values the geometry really sees at controller values q (effects applied). */
    public double[] effectiveQ(double[] q, PoseConditions c) {
        if (effects.isEmpty()) return q.clone();
        double[] theta = model.theta(q);
        double[] dTheta = new double[theta.length];
        for (JointEffect e : effects) e.addDeltaTheta(model, q, c, dTheta);
        for (int i = 0; i < theta.length; i++) theta[i] += dTheta[i];
        return model.q(theta);
    }

    private double strain(PoseConditions c) {
        double s = 0;
        for (JointEffect e : effects) s += e.lengthStrain(c);
        return s;
    }

    /** True baseTflange at controller values q under conditions c, without noise. */
    public Pose flange(double[] q, PoseConditions c) {
        Pose p = model.flange(effectiveQ(q, c));
        double s = strain(c);
        if (s == 0) return p;
        return Pose.translation(p.position().times(s)).times(p);
    }

    /** True baseTflange at q with no effect conditions. */
    public Pose flange(double[] q) { return flange(q, PoseConditions.NONE); }

    /** True baseTtool (the measured point and the tool's orientation) at q, without noise. */
    public Pose tool(double[] q, PoseConditions c) {
        Pose f = model.flange(effectiveQ(q, c));
        Pose t = f.times(flangeTtool);
        double s = strain(c);
        if (s == 0) return t;
        return Pose.translation(t.position().times(s)).times(t);
    }

    /** The measured point's true position in the instrument frame, without noise. */
    public Vec3 point(double[] q, PoseConditions c) {
        return instrumentTbase.apply(tool(q, c).position());
    }

    /** One measurement of the point: the true position in the instrument frame plus Gaussian noise. */
    public Vec3 measure(double[] q, PoseConditions c, Random rng) {
        Vec3 p = point(q, c);
        return new Vec3(p.x() + sigmaM * rng.nextGaussian(), p.y() + sigmaM * rng.nextGaussian(),
                p.z() + sigmaM * rng.nextGaussian());
    }

    /** One measurement of the tool's orientation in the instrument frame, as a quaternion (w, x, y, z). */
    public double[] measureOrientation(double[] q, PoseConditions c, Random rng) {
        Pose r = instrumentTbase.times(tool(q, c));
        Pose noise = Pose.IDENTITY;
        double ex = sigmaRotRad * rng.nextGaussian(), ey = sigmaRotRad * rng.nextGaussian(), ez = sigmaRotRad * rng.nextGaussian();
        double angle = Math.sqrt(ex * ex + ey * ey + ez * ez);
        if (angle > 0) noise = Pose.rotAxis(new Vec3(ex, ey, ez), angle);
        return noise.times(r).quaternion();
    }
}
