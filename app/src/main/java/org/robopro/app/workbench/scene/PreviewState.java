package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.material.Material;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import java.util.List;
import org.robopro.app.workbench.model.DefaultCell;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.JointDescription;
import org.robopro.models.JointType;

/**
 * The robot model being built in the model wizard (seed paper Fig. 7/8): at the zero position,
 * each joint drawn on its axis (revolute: an orange drum, prismatic: a blue sleeve) and named
 * beside it, with the links as grey beams from joint to joint and to the flange, and the model's frames as x/y/z
 * triads (the kinematic model's link frames). Rebuilt when the model's preview changes; while a
 * preview is shown the cell's robot is hidden ({@link RobotState}).
 */
public final class PreviewState extends BaseAppState {
    private final WorkbenchModel model;
    private final Node parent;
    private final Node node = new Node("model-preview");
    private Shapes shapes;
    private WorkbenchModel.ModelPreview built;

    public PreviewState(WorkbenchModel model, Node parent) {
        this.model = model;
        this.parent = parent;
    }

    /** Children drawn for the current preview (tests count frames). */
    public int frameCount() { return built == null ? 0 : built.frames().length; }

    /** Parts drawn whose name starts with {@code prefix}: "preview-joint-" (drums, sleeves), "preview-link-" (links). */
    public long partCount(String prefix) {
        return node.getChildren().stream().filter(c -> c.getName() != null && c.getName().startsWith(prefix)).count();
    }

    @Override protected void initialize(Application app) { shapes = new Shapes(app.getAssetManager()); }
    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { parent.attachChild(node); }
    @Override protected void onDisable() { node.removeFromParent(); }

    @Override
    public void update(float tpf) {
        WorkbenchModel.ModelPreview p = model.preview();
        if (p == built) return;
        built = p;
        node.detachAllChildren();
        if (p == null) return;
        Shapes.apply(model.worldTbase(), node);
        List<JointDescription> js = p.robot().joints();
        double reach = 0.3;
        for (Pose f : p.frames()) reach = Math.max(reach, f.position().norm());
        float r = (float) (0.05 * reach);
        float textHeight = Math.max(0.06f, 0.05f * (float) reach);
        Material drum = shapes.lit(DefaultCell.ABB_ORANGE), sleeve = shapes.lit(0x4F7CAC), link = shapes.lit(0x8A9099);
        Vector3f prev = new Vector3f();
        for (int i = 0; i < js.size(); i++) {
            JointDescription j = js.get(i);
            Vector3f c = Shapes.v(j.point());
            Vector3f a = Shapes.v(j.axis().normalized());
            node.attachChild(shapes.disc("preview-joint-" + (i + 1), c, a, j.type() == JointType.REVOLUTE ? r : r * 0.7f, r * 1.6f,
                    j.type() == JointType.REVOLUTE ? drum : sleeve));
            // The joint axis itself, thin and long, so its direction reads at a glance.
            node.attachChild(shapes.disc("preview-axis-" + (i + 1), c, a, r * 0.12f, r * 5f, shapes.flat(0x202020, false)));
            if (c.distance(prev) > 1e-6f) node.attachChild(shapes.beam("preview-link-" + i, prev, c, r * 0.45f, link));
            // The joint's name above its drum, facing the camera and drawn over the drums and triads.
            Node label = shapes.label("preview-label-" + (i + 1), j.name(), textHeight, 0x101010, true);
            // Joints on the same point (a wrist) stack their names instead of printing them over each other.
            int same = 0;
            for (int k = 0; k < i; k++) if (Shapes.v(js.get(k).point()).distance(c) < 1e-6f) same++;
            label.setLocalTranslation(c.add(r * 1.3f, 0, r * 1.3f + same * 1.3f * textHeight));
            node.attachChild(label);
            prev = c;
        }
        Pose[] f = p.frames();
        Vector3f flange = Shapes.v(f[f.length - 1].position());
        if (flange.distance(prev) > 1e-6f) node.attachChild(shapes.beam("preview-link-" + js.size(), prev, flange, r * 0.35f, link));
        for (int i = 0; i < f.length; i++) {
            Node ax = shapes.axes("preview-frame-" + i, (float) (i == f.length - 1 ? 0.25 * reach : 0.15 * reach));
            Shapes.apply(f[i], ax);
            node.attachChild(ax);
        }
    }
}
