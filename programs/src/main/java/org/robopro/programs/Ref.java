package org.robopro.programs;

/**
 * An instruction argument that is either the name of declared (or predefined) data or a value
 * written inline (RobotStudio's "*" targets: {@code MoveL [[...]], v100, z10, tool0;}).
 */
public sealed interface Ref<T extends RapidValue> permits Ref.Named, Ref.Inline {

    static <T extends RapidValue> Ref<T> to(String name) { return new Named<>(name); }

    static <T extends RapidValue> Ref<T> inline(T value) { return new Inline<>(value); }

    /** The name, or "*" for an inline value (as the RobotStudio path list shows it). */
    String label();

    record Named<T extends RapidValue>(String name) implements Ref<T> {
        public Named {
            if (name == null || name.isEmpty()) throw new IllegalArgumentException("reference needs a name");
        }
        @Override public String label() { return name; }
    }

    record Inline<T extends RapidValue>(T value) implements Ref<T> {
        public Inline {
            if (value == null) throw new IllegalArgumentException("inline value must not be null");
        }
        @Override public String label() { return "*"; }
    }
}
