package org.robopro.programs;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/**
 * Making targets: taught from jogged joint values (forward kinematics, confdata of those joint
 * values), typed poses given a configuration from the inverse-kinematics solution actually
 * used, and welding seams generated along a part edge.
 */
public final class Teach {
    private Teach() { }

    /** The work object's object frame in base coordinates (robot-held tool, fixed work object). */
    public static Pose baseTobj(WObjData wobj) {
        return wobj.uframe().toPose().times(wobj.oframe().toPose());
    }

    /** A robtarget taught at joint values q (rad): the TCP pose in the work object and confdata of q. */
    public static RobTarget taught(KinematicModel model, double[] q, ToolData tool, WObjData wobj) {
        Pose baseTtcp = model.flange(q).times(tool.tframe().toPose());
        Pose objTtcp = baseTobj(wobj).inverse().times(baseTtcp);
        return RobTarget.of(objTtcp, InverseKinematics.of(model).confOf(q));
    }

    /**
     * A typed target pose (TCP in the work object) with the confdata of the IK solution nearest
     * to {@code qSeed}; empty when no solution inside the limits reaches it.
     */
    public static Optional<RobTarget> typed(InverseKinematics ik, Pose objTtcp, ToolData tool, WObjData wobj, double[] qSeed) {
        Pose baseTflange = baseTobj(wobj).times(objTtcp).times(tool.tframe().toPose().inverse());
        return ik.solveNear(baseTflange, qSeed).filter(IkSolution::withinLimits).map(s -> RobTarget.of(objTtcp, s.conf()));
    }

    /**
     * A straight welding seam on a part edge, in work-object coordinates.
     *
     * @param start        seam start, m
     * @param end          seam end, m
     * @param normal       surface normal at the seam (away from the part)
     * @param workAngle    tilt of the torch about the seam (travel) axis, rad
     * @param travelAngle  tilt along the seam (positive pushes: torch leans towards the travel direction), rad
     * @param passOffsets  per pass, {lateral, height} offsets of the seam line, m
     * @param approach     distance of approach and retract points above the seam, m
     */
    public record Seam(Vec3 start, Vec3 end, Vec3 normal, double workAngle, double travelAngle, List<double[]> passOffsets,
                       double approach) { }

    /** The generated targets of a seam: per pass approach, start, end, retract; names "{prefix}{pass}_{what}". */
    public record SeamTargets(List<String> names, List<RobTarget> targets) { }

    /**
     * Seam targets with confdata from IK solutions that follow each other from {@code qSeed}
     * (so a pass keeps one configuration). Throws IllegalArgumentException naming the point
     * when a target is not reachable inside the limits.
     */
    public static SeamTargets seam(InverseKinematics ik, Seam seam, ToolData tool, WObjData wobj, double[] qSeed, String prefix) {
        Vec3 x = seam.end().minus(seam.start()).normalized();
        Vec3 nz = seam.normal().minus(x.times(seam.normal().dot(x))).normalized();
        Vec3 z = nz.times(-1); // the torch points into the seam
        Vec3 y = z.cross(x);
        Pose seamFrame = Pose.of(new double[] {x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z()}, 0, 0, 0);
        Pose torch = seamFrame.times(Pose.rotX(seam.workAngle())).times(Pose.rotY(-seam.travelAngle()));
        List<String> names = new ArrayList<>();
        List<RobTarget> targets = new ArrayList<>();
        double[] q = qSeed.clone();
        for (int p = 0; p < seam.passOffsets().size(); p++) {
            double[] off = seam.passOffsets().get(p);
            Vec3 shift = y.times(off[0]).plus(nz.times(off[1]));
            Vec3 s = seam.start().plus(shift), e = seam.end().plus(shift), up = nz.times(seam.approach());
            Vec3[] pts = {s.plus(up), s, e, e.plus(up)};
            String[] what = {"app", "start", "end", "ret"};
            for (int k = 0; k < 4; k++) {
                Pose objTtcp = Pose.of(torch.rotationRowMajor(), pts[k].x(), pts[k].y(), pts[k].z());
                Pose baseTflange = baseTobj(wobj).times(objTtcp).times(tool.tframe().toPose().inverse());
                String name = prefix + (p + 1) + "_" + what[k];
                IkSolution sol = ik.solveNear(baseTflange, q).filter(IkSolution::withinLimits)
                        .orElseThrow(() -> new IllegalArgumentException("seam point " + name + " is out of reach"));
                q = sol.q();
                names.add(name);
                targets.add(RobTarget.of(objTtcp, sol.conf()));
            }
        }
        return new SeamTargets(names, targets);
    }
}
