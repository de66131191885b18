package org.robopro.app.workbench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robopro.app.workbench.model.CellObject;
import org.robopro.kinematics.Pose;
import org.robopro.models.Vec3;

/** The live collision view's data, headless: jogging the torch down onto the plates of the welding cell. */
class LiveClearanceTest {
    @TempDir Path dir;
    private WorkbenchSession s;

    @BeforeEach
    void open() throws Exception {
        System.setProperty("robopro.autosaveDir", dir.resolve("autosave").toString());
        s = WorkbenchSession.open(null);
    }

    @AfterEach
    void close() { s.close(); }

    /** Distance from a point to a standing box (frame at the centre of its underside), computed here independently of GJK. */
    static double distanceToBox(Vec3 p, CellObject o) {
        Vec3 l = o.worldTobject().inverse().apply(p);
        double dx = Math.max(0, Math.abs(l.x()) - o.size().x() / 2);
        double dy = Math.max(0, Math.abs(l.y()) - o.size().y() / 2);
        double dz = Math.max(0, Math.max(-l.z(), l.z() - o.size().z()));
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Test
    void jogDownOntoThePlates_nearThenCollidingWithTheTool_closestPairNamed() {
        LiveClearance.Reading ready = s.clearance().current().orElseThrow();
        assertFalse(ready.colliding(), ready.text());
        assertTrue(ready.snapshot().minClearanceM() > 0, ready.text());
        assertSame(ready, s.clearance().current().orElseThrow(), "no new reading while the joints stand still");

        LiveClearance.Reading before = ready, hit = null;
        for (int step = 0; step < 200 && hit == null; step++) {
            assertTrue(s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0, -0.005, 0, 0, 0), "jog step " + step);
            LiveClearance.Reading r = s.clearance().current().orElseThrow();
            if (r.colliding()) hit = r;
            else before = r;
        }
        assertTrue(hit != null, "jogging 1 m down must hit the plates or the table");
        assertTrue(hit.text().startsWith("COLLISION"), hit.text());
        assertEquals(LiveClearance.Level.COLLIDING, hit.highlights().get("tool"), hit.highlights().toString());
        String object = hit.highlights().keySet().stream().filter(k -> k.startsWith("object:")).findFirst().orElseThrow();
        assertEquals(LiveClearance.Level.COLLIDING, hit.highlights().get(object));
        // The torch's capsule (25 mm radius) ends at the TCP: at the first contact the TCP is within
        // that radius of the object, plus one 5 mm step; one step earlier it was not in contact.
        CellObject o = s.model().object(object.substring(7)).orElseThrow();
        double d = distanceToBox(s.model().worldTtcp().position(), o);
        assertTrue(d <= 0.025 + 1e-6, "TCP " + d * 1e3 + " mm from " + o.name() + " at first contact");
        assertTrue(before.snapshot().minClearanceM() < 0.005 + 1e-6 && before.snapshot().minClearanceM() > 0, before.text());
        assertEquals(LiveClearance.Level.NEAR, before.highlights().get("tool"), before.text());
        assertTrue(before.snapshot().closestParts().contains("tool"), before.snapshot().closestParts().toString());
    }

    @Test
    void partPlacedThroughAnother_warnedInTheStatusLine_restingObjectsAreNot() {
        LiveClearance.Reading ready = s.clearance().current().orElseThrow();
        assertTrue(ready.placement().isEmpty(), "the welding cell's objects rest on one another: " + ready.placement());
        CellObject a = s.addObject(CellObject.Kind.PART);
        CellObject b = s.addObject(CellObject.Kind.PART);
        s.placeObject(a.id(), 2.0, 2.0, 0.0, 0);
        s.placeObject(b.id(), 2.05, 2.0, 0.0, 0);
        LiveClearance.Reading r = s.clearance().current().orElseThrow();
        assertEquals(1, r.placement().size(), r.placement().toString());
        assertTrue(r.placement().get(0).contains("placed through"), r.placement().toString());
        assertTrue(r.text().contains("WARNING: ") && r.text().contains("placed through"), r.text());
        // Moved apart: the warning goes.
        s.placeObject(b.id(), 3.5, 2.0, 0.0, 0);
        assertTrue(s.clearance().current().orElseThrow().placement().isEmpty());
    }

    @Test
    void objectMovedOntoTheRobot_checkerFollowsTheCell() {
        double[] q = s.model().q();
        LiveClearance.Reading ready = s.clearance().current().orElseThrow();
        CellObject box = s.addObject(CellObject.Kind.PART);
        // Put the new part where the tool is now.
        Vec3 tcp = s.model().worldTtcp().position();
        s.placeObject(box.id(), tcp.x(), tcp.y(), tcp.z() - 0.02, 0);
        assertEquals(q.length, s.model().q().length);
        LiveClearance.Reading r = s.clearance().current().orElseThrow();
        assertTrue(r.colliding(), r.text());
        assertEquals(LiveClearance.Level.COLLIDING, r.highlights().get("object:" + box.id()), r.highlights().toString());
        assertFalse(ready.colliding());
    }

    @Test
    void programIntoThePlate_collisionOnItsInstruction_otherMovesClear() throws Exception {
        s.teach(); // p10 at the ready pose, torch over the plates
        for (int i = 0; i < 200 && !s.clearance().current().orElseThrow().colliding(); i++)
            assertTrue(s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0, -0.005, 0, 0, 0));
        s.jogCartesian(WorkbenchSession.JogFrame.WORLD, 0, 0, -0.005, 0, 0, 0); // 5 mm into it
        assertTrue(s.clearance().current().orElseThrow().colliding(), "the torch is in the plate");
        s.teach(); // p20, in the plate
        s.addMove(org.robopro.app.workbench.model.Instruction.Type.MOVEJ, "p10", 500, 0);
        s.addMove(org.robopro.app.workbench.model.Instruction.Type.MOVEL, "p20", 100, 0);
        s.addMove(org.robopro.app.workbench.model.Instruction.Type.MOVEL, "p10", 100, 0);
        var run = s.awaitPathCheck().run();
        var steps = run.steps();
        assertTrue(steps.get(0).ok(), steps.get(0).message());
        for (int k = 1; k <= 2; k++) {
            var st = steps.get(k);
            assertTrue(!st.ok() && st.problems().stream().anyMatch(p -> p.kind() == org.robopro.programs.check.Problem.Kind.COLLISION),
                    "move " + k + " into / out of the plate collides: " + st.problems());
        }
        assertTrue(run.badTargets().contains("p20"), run.badTargets().toString());
    }

    @Test
    void robotShapes_capsulesFollowTheLinks() {
        var shapes = s.clearance().robotShapes(s.model().q());
        assertTrue(shapes.containsKey("tool") && shapes.containsKey("link:1"), shapes.keySet().toString());
        // The tool capsule ends at the TCP (base coordinates).
        Pose baseTtcp = s.model().worldTbase().inverse().times(s.model().worldTtcp());
        assertEquals(0, shapes.get("tool").b().minus(baseTtcp.position()).norm(), 1e-9);
    }
}
