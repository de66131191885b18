package org.robopro.app.workbench.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Locale;
import org.junit.jupiter.api.Test;

/** The jog panel's read-out of the TCP: a component that rounds to zero shows as zero, without a sign. */
class JogPanelTest {
    @Test
    void shown_valuesThatRoundToZeroHaveNoSign_othersKeepTheirs() {
        for (double v : new double[] {-0.0, 0.0, -1e-17, -4.9e-5, 4.9e-5})
            assertEquals("0.0000", String.format(Locale.ROOT, "%.4f", JogPanel.shown(v, 1e-4)), "q component " + v);
        assertEquals("-0.0001", String.format(Locale.ROOT, "%.4f", JogPanel.shown(-6e-5, 1e-4)));
        assertEquals("-0.9924", String.format(Locale.ROOT, "%.4f", JogPanel.shown(-0.9924038765, 1e-4)));
        assertEquals("0.0", String.format(Locale.ROOT, "%.1f", JogPanel.shown(-0.04, 0.1)), "mm");
        assertEquals("1284.1", String.format(Locale.ROOT, "%.1f", JogPanel.shown(1284.06, 0.1)));
    }
}
