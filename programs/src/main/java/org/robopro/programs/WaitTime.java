package org.robopro.programs;

/** {@code WaitTime s;}: program execution waits {@code seconds} (s); robopro adds it to the cycle time. */
public record WaitTime(double seconds) implements Statement {
    public WaitTime {
        if (!(seconds >= 0) || !Double.isFinite(seconds)) throw new IllegalArgumentException("WaitTime needs a finite time >= 0, got " + seconds);
    }
}
