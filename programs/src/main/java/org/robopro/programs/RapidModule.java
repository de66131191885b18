package org.robopro.programs;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.programs.rapid.RapidAst;

/**
 * A RAPID program module. The program is its syntax tree ({@link #tree()}); everything else here
 * is a read-only typed view computed from that tree: items in file order (declarations of the
 * data types robopro reads typed, parameterless procedures with their Moves, WaitTimes and calls,
 * comment lines; anything else as {@link AstItem}/{@link AstStatement}). Building a module from
 * typed items ({@link #of(String, List, List)}, {@link #builder}, {@link #withItems}) produces a
 * tree first (names as given, numbers as literals that read back as the same doubles), and the
 * view is read back from it; a typed item left unchanged by {@link #withItems} keeps its tree
 * node, so an edit rewrites only the statements it touches. Immutable. RAPID names are
 * case-insensitive, so every look-up here is.
 */
public final class RapidModule {
    private final RapidAst.Module tree;
    /** The typed view of {@link #tree}, read on first use. */
    private volatile View view;

    /** Typed items and, for each typed item and statement, the tree node it was read from. */
    record View(List<ModuleItem> items, IdentityHashMap<Object, Object> nodes) {
        View {
            items = List.copyOf(items);
        }
    }

    RapidModule(RapidAst.Module tree, View view) {
        if (tree == null) throw new IllegalArgumentException("tree must not be null");
        this.tree = tree;
        this.view = view;
    }

    /** The module a syntax tree is; data or statements robopro cannot read typed stay syntax tree in the view. */
    public static RapidModule of(RapidAst.Module tree) { return new RapidModule(tree, null); }

    /** The module whose tree these typed items stand for (name, module options, items in file order). */
    public static RapidModule of(String name, List<String> options, List<ModuleItem> items) {
        List<RapidAst.Item> out = new ArrayList<>();
        for (ModuleItem it : items) out.add(RapidWriter.exactItem(it, Map.of()));
        return of(new RapidAst.Module(name, options, out));
    }

    /** The program: the syntax tree the interpreter runs and the writer writes. */
    public RapidAst.Module tree() { return tree; }

    public String name() { return tree.name(); }

    public List<String> options() { return tree.options(); }

    public List<ModuleItem> items() { return view().items(); }

    private View view() {
        View v = view;
        if (v == null) view = v = RapidParser.view(tree);
        return v;
    }

    /** The tree node {@code item} (an item or statement of this module's view, this very object) was read from. */
    public Optional<Object> node(Object item) { return Optional.ofNullable(view().nodes().get(item)); }

    public List<Declaration> declarations() {
        List<Declaration> out = new ArrayList<>();
        for (ModuleItem i : items()) if (i instanceof Declaration d) out.add(d);
        return out;
    }

    public List<Procedure> procedures() {
        List<Procedure> out = new ArrayList<>();
        for (ModuleItem i : items()) if (i instanceof Procedure p) out.add(p);
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

    /**
     * The module with these items: items and statements of this module's view passed back
     * unchanged (the same objects) keep their tree nodes as written; new or changed ones are
     * written as new nodes.
     */
    public RapidModule withItems(List<ModuleItem> newItems) {
        Map<Object, Object> nodes = view().nodes();
        List<RapidAst.Item> out = new ArrayList<>();
        for (ModuleItem it : newItems) {
            Object n = nodes.get(it);
            out.add(n instanceof RapidAst.Item i ? i : RapidWriter.exactItem(it, nodes));
        }
        return of(new RapidAst.Module(tree.name(), tree.options(), out));
    }

    /** The same module with another tree (an edit of {@link #tree()}). */
    public RapidModule withTree(RapidAst.Module newTree) { return of(newTree); }

    @Override public boolean equals(Object o) { return o instanceof RapidModule m && m.tree.equals(tree); }

    @Override public int hashCode() { return tree.hashCode(); }

    @Override public String toString() { return "RapidModule[" + tree.name() + ", " + tree.items().size() + " items]"; }

    public static Builder builder(String name) { return new Builder(name); }

    /** Collects declarations and procedures (declarations first, as RAPID style wants) into a module's tree. */
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
            return RapidModule.of(name, options, all);
        }
    }
}
