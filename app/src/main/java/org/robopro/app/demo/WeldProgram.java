package org.robopro.app.demo;

import java.util.ArrayList;
import java.util.List;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.models.CellDescription;
import org.robopro.models.CellObject;
import org.robopro.models.PoseDescription;
import org.robopro.models.ToolDescription;
import org.robopro.models.Vec3;
import org.robopro.models.WorkObjectDescription;
import org.robopro.programs.JointTarget;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.Procedure;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.Statement;
import org.robopro.programs.Teach;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;

/**
 * The demo's welding program, taught off-line in the shipped {@code irb2000-welding} cell: a T
 * fillet seam where the web plate stands on the base plate (the edge facing the robot), welded
 * in three passes with {@link Teach#seam}; each pass is approach (MoveJ), start, end, retract
 * (MoveL), between MoveAbsJ to a home position.
 */
final class WeldProgram {
    static final String MODULE = "DemoWeld";
    static final String TOOL = "tTorch", WOBJ = "wTable", HOME = "jHome";
    /** Home: the arm leaning towards the table, wrist bent down (deg). */
    static final double[] HOME_DEG = {0, 20, 10, 0, 50, 0};

    final ToolData torch;
    final WObjData table;
    final Pose flangeTtcp;
    final RapidModule module;
    final int passes;

    private WeldProgram(ToolData torch, WObjData table, RapidModule module, int passes) {
        this.torch = torch;
        this.table = table;
        this.flangeTtcp = torch.tframe().toPose();
        this.module = module;
        this.passes = passes;
    }

    static Pose pose(PoseDescription d) {
        return Pose.fromQuaternion(d.qw(), d.qx(), d.qy(), d.qz(), d.position().x(), d.position().y(), d.position().z());
    }

    static double[] homeRad() {
        double[] q = new double[HOME_DEG.length];
        for (int i = 0; i < q.length; i++) q[i] = Math.toRadians(HOME_DEG[i]);
        return q;
    }

    private static CellObject object(CellDescription cell, String name) {
        return cell.objects().stream().filter(o -> o.name().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("cell " + cell.name() + " has no object '" + name + "'"));
    }

    /** The cell's welding torch, flangeTtcp. */
    static Pose torch(CellDescription cell) {
        return pose(cell.tools().stream().filter(t -> t.name().equals("torch")).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("cell " + cell.name() + " has no tool 'torch'")).flangeTtcp());
    }

    /** Teaches the program in {@code cell} (the shipped welding cell: torch, wobj_table, base_plate, web_plate). */
    static WeldProgram teach(CellDescription cell, KinematicModel nominal, int passes) {
        ToolDescription td = cell.tools().stream().filter(t -> t.name().equals("torch")).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("cell " + cell.name() + " has no tool 'torch'"));
        WorkObjectDescription wd = cell.workObjects().stream().filter(w -> w.name().equals("wobj_table")).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("cell " + cell.name() + " has no work object 'wobj_table'"));
        Pose worldTbase = pose(cell.worldTbase());
        Pose baseTuser = worldTbase.inverse().times(pose(wd.worldTuser()));
        ToolData torch = new ToolData(true, RapidPose.of(pose(td.flangeTtcp())),
                new LoadData(td.massKg(), td.centreOfMass(), Quaternion.IDENTITY, 0, 0, 0));
        WObjData table = new WObjData(false, true, "", RapidPose.of(baseTuser), RapidPose.IDENTITY);

        // The seam: the web plate's face towards the robot meets the base plate's top (boxes are axis-aligned in this cell).
        CellObject base = object(cell, "base_plate"), web = object(cell, "web_plate");
        Pose worldTweb = pose(web.worldTobject()), worldTbasePlate = pose(base.worldTobject());
        double faceX = worldTweb.x() - web.size().x() / 2, topZ = worldTbasePlate.z() + base.size().z() / 2;
        double half = web.size().y() / 2 - 0.010; // 10 mm in from the plate edges
        Pose userTworld = baseTuser.inverse().times(worldTbase.inverse());
        Vec3 start = userTworld.apply(new Vec3(faceX, worldTweb.y() - half, topZ));
        Vec3 end = userTworld.apply(new Vec3(faceX, worldTweb.y() + half, topZ));
        Vec3 normal = new Vec3(-1, 0, 1).normalized(); // bisects the fillet: towards the robot and up
        List<double[]> offsets = new ArrayList<>();
        double[][] pattern = {{0, 0}, {0.003, 0.002}, {-0.003, 0.002}, {0, 0.004}};
        for (int p = 0; p < passes; p++) offsets.add(pattern[p % pattern.length]);
        Teach.Seam seam = new Teach.Seam(start, end, normal, 0, Math.toRadians(10), offsets, 0.05);
        Teach.SeamTargets st = Teach.seam(InverseKinematics.of(nominal), seam, torch, table, homeRad(), "pW");

        RapidModule.Builder b = RapidModule.builder(MODULE)
                .comment(" T fillet seam on the irb2000-welding cell, " + passes + " passes, taught off-line by robopro demo")
                .pers(TOOL, torch).pers(WOBJ, table).constant(HOME, JointTarget.of(homeRad()));
        List<Statement> body = new ArrayList<>();
        body.add(Move.moveAbsJ(Ref.to(HOME), Ref.to("v1000"), Ref.to("fine"), TOOL, null));
        for (int k = 0; k < st.names().size(); k++) {
            String name = st.names().get(k);
            b.constant(name, st.targets().get(k));
            int what = k % 4; // approach, start, end, retract
            body.add(what == 0 ? Move.moveJ(Ref.to(name), Ref.to("v500"), Ref.to("fine"), TOOL, WOBJ)
                    : Move.moveL(Ref.to(name), Ref.to(what == 2 ? "v20" : "v100"), Ref.to("fine"), TOOL, WOBJ));
        }
        body.add(Move.moveAbsJ(Ref.to(HOME), Ref.to("v1000"), Ref.to("fine"), TOOL, null));
        return new WeldProgram(torch, table, b.procedure("main", body).build(), passes);
    }

    /** The module with {@code main} cut after statement {@code lastIndex} (0-based): run it to stop the robot there. */
    static RapidModule truncated(RapidModule m, int lastIndex) {
        List<org.robopro.programs.ModuleItem> items = new ArrayList<>();
        for (org.robopro.programs.ModuleItem it : m.items()) {
            if (it instanceof Procedure p && p.name().equalsIgnoreCase("main"))
                items.add(p.withBody(p.body().subList(0, lastIndex + 1)));
            else items.add(it);
        }
        return m.withItems(items);
    }
}
