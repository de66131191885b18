package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.robopro.app.workbench.WorkbenchSession;

/** The robot model wizard's own undo and redo over its table edits, joints added, name and template changes. */
class RobotWizardUndoTest {
    @Test
    void wizardEdits_undoneAndRedoneInOrder_newEditClearsRedo() throws Exception {
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            RobotWizard w = new RobotWizard(null, s);
            String start = w.wizardModel().state().key();
            double z3 = w.wizardModel().joint(2).pointMm()[2];
            assertFalse(w.canUndo());

            w.setJointCell(2, "Z mm", z3 + 100);        // a longer upper arm
            String longer = w.wizardModel().state().key();
            w.addJoint();                                 // a seventh joint
            w.setFlangeCell(0, 0, 1234);                  // flange origin x
            w.setRobotName("irb2000_long", "IRB 2000 long arm");
            assertEquals(7, w.wizardModel().jointCount());

            assertTrue(w.undo());
            assertEquals("irb2000_custom", w.wizardModel().name(), "name undone first");
            assertTrue(w.undo());
            assertNotEquals(1234, w.wizardModel().flangeOriginMm()[0], 1e-9);
            assertTrue(w.undo());
            assertEquals(6, w.wizardModel().jointCount(), "added joint undone");
            assertEquals(longer, w.wizardModel().state().key());
            assertTrue(w.result().ok(), "the model builds again after undo");
            assertTrue(w.undo());
            assertEquals(start, w.wizardModel().state().key(), "back to the template");
            assertEquals(z3, w.wizardModel().joint(2).pointMm()[2], 1e-9);
            assertFalse(w.undo(), "nothing left to undo");

            assertTrue(w.redo());
            assertEquals(longer, w.wizardModel().state().key(), "redo replays the table edit");
            w.setJointCell(0, "Joint", "base_turn");       // a new edit drops the redo steps
            assertFalse(w.redo());

            w.startFrom("puma560");
            assertEquals("puma560_custom", w.wizardModel().name());
            assertTrue(w.undo());
            assertEquals("base_turn", w.wizardModel().joint(0).name(), "starting over is undone like any edit");
        }
    }
}
