package org.robopro.models;

import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A robot as robopro's robot files describe it (docs/robot-file.md): the seed paper's inputs per
 * joint, the flange at the zero position, joint coupling, an optional mass model, meshes, an
 * optional extended (non-geometric) model, and where the numbers come from. Immutable, SI units.
 *
 * @param name        short identifier ("irb2000")
 * @param displayName human name ("ABB IRB 2000")
 * @param joints      joints from base to flange
 * @param flange      flange (tool0) frame in base coordinates at the zero position
 * @param coupling    theta = C q terms; empty for none
 * @param massModel   optional mass model
 * @param meshes      optional meshes
 * @param effects     optional non-geometric effects (extended model)
 * @param source      where the numbers come from
 * @param provenance  free key/value history (e.g. "calibrated-from": file, "date": ...)
 */
public record RobotDescription(String name, String displayName, List<JointDescription> joints,
                               FrameDescription flange, List<CouplingTerm> coupling,
                               Optional<MassModel> massModel, List<MeshRef> meshes,
                               List<EffectDescription> effects, String source,
                               Map<String, String> provenance) {
    /** Most joints a robot may have (serial arms have 4 to 7; with a track and positioner a dozen). */
    public static final int MAX_JOINTS = 64;
    /** Largest coordinate in a robot or cell file, m: a kilometre is beyond any cell. */
    public static final double MAX_COORDINATE_M = 1000;

    public RobotDescription {
        joints = List.copyOf(joints);
        coupling = List.copyOf(coupling);
        meshes = List.copyOf(meshes);
        effects = List.copyOf(effects);
        provenance = Map.copyOf(provenance);
    }

    public int dof() { return joints.size(); }

    /** The coupling matrix C (theta = C q), identity where no term is given. */
    public double[][] couplingMatrix() {
        int n = joints.size();
        double[][] c = new double[n][n];
        boolean[] touched = new boolean[n];
        for (CouplingTerm t : coupling) touched[t.joint() - 1] = true;
        for (int i = 0; i < n; i++) if (!touched[i]) c[i][i] = 1;
        for (CouplingTerm t : coupling) c[t.joint() - 1][t.source() - 1] += t.factor();
        return c;
    }

    public RobotDescription withJointsAndFlange(List<JointDescription> newJoints, FrameDescription newFlange) {
        return new RobotDescription(name, displayName, newJoints, newFlange, coupling, massModel, meshes,
                effects, source, provenance);
    }

    public RobotDescription withEffects(List<EffectDescription> newEffects) {
        return new RobotDescription(name, displayName, joints, flange, coupling, massModel, meshes,
                newEffects, source, provenance);
    }

    public RobotDescription withProvenance(Map<String, String> newProvenance) {
        return new RobotDescription(name, displayName, joints, flange, coupling, massModel, meshes,
                effects, source, newProvenance);
    }
}
