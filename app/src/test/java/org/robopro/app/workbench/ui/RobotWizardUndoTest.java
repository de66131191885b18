package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.CellObject;

/**
 * The robot model wizard's edits share the workbench's one undo history (Edit &gt; Undo, Ctrl+Z):
 * table edits, joints added, the name and template changes are taken back in the order they
 * were made, interleaved with edits of the cell, and redone; a new edit drops what could be redone.
 */
class RobotWizardUndoTest {
    @Test
    void wizardEdits_undoneByTheSessionUndoInOrderWithCellEdits_newEditClearsRedo() throws Exception {
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            RobotWizard w = new RobotWizard(null, s);
            String start = w.wizardModel().state().key();
            double z3 = w.wizardModel().joint(2).pointMm()[2];
            int objects = s.model().objects().size();
            assertFalse(s.model().history().undoLabel().isPresent(), "opening the wizard is no edit");

            w.setJointCell(2, "Z mm", z3 + 100);        // a longer upper arm
            assertEquals("Robot model: j3 Z mm", s.model().history().undoLabel().orElseThrow(), "the Edit menu names the wizard edit");
            String longer = w.wizardModel().state().key();
            s.addObject(CellObject.Kind.TABLE);           // a cell edit in between
            w.addJoint();                                 // a seventh joint
            w.setFlangeCell(0, 0, 1234);                  // flange origin x
            w.setRobotName("irb2000_long", "IRB 2000 long arm");
            assertEquals(7, w.wizardModel().jointCount());
            assertEquals(objects + 1, s.model().objects().size());

            assertTrue(s.undo());
            assertEquals("irb2000_custom", w.wizardModel().name(), "name undone first");
            assertTrue(s.undo());
            assertNotEquals(1234, w.wizardModel().flangeOriginMm()[0], 1e-9);
            assertTrue(s.undo());
            assertEquals(6, w.wizardModel().jointCount(), "added joint undone");
            assertEquals(longer, w.wizardModel().state().key());
            assertTrue(w.result().ok(), "the model builds again after undo");
            assertEquals(objects + 1, s.model().objects().size(), "the cell edit is not taken back with the wizard's");
            assertTrue(s.undo());
            assertEquals(objects, s.model().objects().size(), "then the table added between the wizard edits");
            assertEquals(longer, w.wizardModel().state().key(), "leaving the wizard as it was");
            assertTrue(s.undo());
            assertEquals(start, w.wizardModel().state().key(), "back to the template");
            assertEquals(z3, w.wizardModel().joint(2).pointMm()[2], 1e-9);
            assertEquals(z3, s.model().preview().robot().joints().get(2).point().z() * 1000, 1e-6, "the 3D preview follows undo");
            assertFalse(s.undo(), "nothing left to undo");

            assertTrue(s.redo());
            assertEquals(longer, w.wizardModel().state().key(), "redo replays the table edit");
            assertTrue(s.redo());
            assertEquals(objects + 1, s.model().objects().size(), "and then the table");
            w.setJointCell(0, "Joint", "base_turn");       // a new edit drops the redo steps
            assertFalse(s.redo());

            w.startFrom("puma560");
            assertEquals("puma560_custom", w.wizardModel().name());
            assertEquals("Robot model: start from puma560", s.model().history().undoLabel().orElseThrow());
            assertTrue(s.undo());
            assertEquals("base_turn", w.wizardModel().joint(0).name(), "starting over is undone like any edit");
        }
    }

    @Test
    void typingInTheSameCell_mergesIntoOneEdit() throws Exception {
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            RobotWizard w = new RobotWizard(null, s);
            String start = w.wizardModel().state().key();
            for (int i = 1; i <= 5; i++) w.setJointCell(1, "Z mm", 780 + i);
            assertEquals(1, s.model().history().undoSize(), "quick edits of one cell are one command");
            assertTrue(s.undo());
            assertEquals(start, w.wizardModel().state().key());
        }
    }
}
