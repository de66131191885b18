package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Component;
import java.awt.Container;
import javax.swing.JComboBox;
import org.junit.jupiter.api.Test;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.Target;

/** The program panel as it first opens, before any edit. */
class ProgramPanelTest {
    @Test
    void opened_teachInShowsTheActiveWorkObjectAndListsEveryWorkObject() throws Exception {
        try (WorkbenchSession s = WorkbenchSession.open(null)) {
            ProgramPanel p = new ProgramPanel(s);
            JComboBox<?> wobj = (JComboBox<?>) find(p, "teach-wobj");
            assertEquals(s.model().activeWorkObject(), wobj.getSelectedItem(), "the work object new targets are taught in");
            assertEquals(1 + s.model().workObjects().size(), wobj.getItemCount());
            assertEquals(Target.WOBJ0, wobj.getItemAt(0));
        }
    }

    private static Component find(Container c, String name) {
        for (Component k : c.getComponents()) {
            if (name.equals(k.getName())) return k;
            if (k instanceof Container kc) {
                Component f = find(kc, name);
                if (f != null) return f;
            }
        }
        return null;
    }
}
