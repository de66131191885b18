package org.robopro.app.workbench.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import org.junit.jupiter.api.Test;
import org.robopro.app.workbench.model.WorkbenchModel.FrameKind;

/** View → Frames: each kind of frame on its own, "Show frames" switching the robot's together, no undo step. */
class FrameDisplayTest {
    @Test
    void frames_eachKindOnItsOwn_showFramesSwitchesTheRobotsTogether() {
        WorkbenchModel m = new WorkbenchModel("irb2000", org.robopro.models.RobotLibrary.shipped("irb2000"));
        assertEquals(EnumSet.of(FrameKind.WORLD, FrameKind.TARGETS), EnumSet.copyOf(m.shownFrames()), "default: world triad and target triads");
        var before = m.shownFrames();
        m.setFrameShown(FrameKind.TCP, true);
        assertNotSame(before, m.shownFrames(), "the scene notices a change by a new set");
        assertTrue(m.frameShown(FrameKind.TCP));
        assertFalse(m.showFrames(), "the joint axes stay hidden");
        m.setShowFrames(true);
        assertTrue(m.shownFrames().containsAll(EnumSet.of(FrameKind.BASE, FrameKind.JOINTS, FrameKind.FLANGE, FrameKind.TCP)));
        m.setFrameShown(FrameKind.WORLD, false);
        m.setShowFrames(false);
        assertEquals(EnumSet.of(FrameKind.TARGETS), EnumSet.copyOf(m.shownFrames()));
        assertEquals(0, m.history().undoSize(), "showing frames is not an edit");
    }
}
