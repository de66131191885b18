package org.robopro.programs;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * A RAPID program module: name, module options (SYSMODULE, NOSTEPIN, ...) and its items in file
 * order (declarations, procedures, comment lines). Immutable. RAPID names are case-insensitive,
 * so every look-up here is.
 */
public record RapidModule(String name, List<String> options, List<ModuleItem> items) {
    public RapidModule {
        if (name == null || name.isEmpty()) throw new IllegalArgumentException("module needs a name");
        options = List.copyOf(options);
        items = List.copyOf(items);
    }

    public List<Declaration> declarations() {
        List<Declaration> out = new ArrayList<>();
        for (ModuleItem i : items) if (i instanceof Declaration d) out.add(d);
        return out;
    }

    public List<Procedure> procedures() {
        List<Procedure> out = new ArrayList<>();
        for (ModuleItem i : items) if (i instanceof Procedure p) out.add(p);
        return out;
    }

    public Optional<Declaration> declaration(String n) {
        String k = n.toLowerCase(Locale.ROOT);
        for (Declaration d : declarations()) if (d.name().toLowerCase(Locale.ROOT).equals(k)) return Optional.of(d);
        return Optional.empty();
    }

    public Optional<Procedure> procedure(String n) {
        String k = n.toLowerCase(Locale.ROOT);
        for (Procedure p : procedures()) if (p.name().toLowerCase(Locale.ROOT).equals(k)) return Optional.of(p);
        return Optional.empty();
    }

    public RapidModule withItems(List<ModuleItem> newItems) { return new RapidModule(name, options, newItems); }

    public static Builder builder(String name) { return new Builder(name); }

    /** Collects declarations and procedures (declarations first, as RAPID style wants). */
    public static final class Builder {
        private final String name;
        private final List<String> options = new ArrayList<>();
        private final List<ModuleItem> head = new ArrayList<>();
        private final List<ModuleItem> procs = new ArrayList<>();

        private Builder(String name) { this.name = name; }

        public Builder option(String o) { options.add(o); return this; }

        public Builder comment(String text) { head.add(new Comment(text)); return this; }

        public Builder declare(Declaration d) { head.add(d); return this; }

        public Builder constant(String n, RapidValue v) { return declare(Declaration.constant(n, v)); }

        public Builder pers(String n, RapidValue v) { return declare(Declaration.pers(n, v)); }

        public Builder var(String n, RapidValue v) { return declare(Declaration.var(n, v)); }

        public Builder procedure(String n, List<Statement> body) { procs.add(new Procedure(n, body)); return this; }

        public RapidModule build() {
            List<ModuleItem> all = new ArrayList<>(head);
            all.addAll(procs);
            return new RapidModule(name, options, all);
        }
    }
}
