package org.robopro.app.workbench.model;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.kinematics.ConfData;
import org.robopro.kinematics.IkSolution;
import org.robopro.kinematics.InverseKinematics;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.Vec3;
import org.robopro.programs.LoadData;
import org.robopro.programs.Move;
import org.robopro.programs.Quaternion;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidPose;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.Statement;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.ZoneData;
import org.robopro.programs.ParsedModule;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.sim.MoveStep;
import org.robopro.programs.sim.ProgramStep;
import org.robopro.programs.Declaration;
import org.robopro.programs.Procedure;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidValue;
import org.robopro.programs.RapidWriter;
import org.robopro.programs.rapid.RapidAst;

/**
 * The workbench program as a RAPID module ({@link RapidModule}, programs module) and back.
 *
 * <p>To RAPID, 1:1: the mounted tool is a {@code PERS tooldata}, each work object used by a
 * target a {@code PERS wobjdata}, each target a {@code CONST robtarget} in its work object's
 * frame with the confdata of the IK solution the workbench uses for it (solved next to the
 * joints it was taught at) — a target only MoveAbsJ goes to is a {@code CONST jointtarget} of its
 * joints instead — each instruction one {@code MoveJ/MoveL/MoveC/MoveAbsJ} statement of
 * {@code PROC main} (statement k is instruction k). The RAPID world frame is the robot base
 * (as the programs module's interpreter takes it): work object user frames are written as
 * {@code baseTuser = worldTbase^-1 worldTuser}.
 *
 * <p>From RAPID: the program is a view of the module's syntax tree. Each statement of the entry
 * procedure is one line: a motion run once at the top level becomes an editable instruction
 * (linked to its statement); every other statement (waits, I/O, calls, comments, loops, process
 * instructions) is kept as written ({@link Instruction.Type#RAPID}, shown read-only). A target or
 * work object equal in value to one the cell has already (same frame, same pose) is that one,
 * so importing twice adds nothing; named robtargets and jointtargets keep their names, inline
 * ones get fresh names; MoveAbsJ stays MoveAbsJ (its target holds the joints). The module is
 * kept ({@link Source}); exporting writes it back with only what was edited rewritten
 * ({@link #toRapid(WorkbenchModel, String)}): unchanged statements, declarations, other
 * routines and comments come out as they were read. What was changed is listed in
 * {@link Imported#notes()}.
 */
public final class ProgramModule {
    private ProgramModule() { }

    /** The RAPID module a program was imported from and the procedure it was read from. */
    public record Source(RapidModule module, String entry) {
        public Source {
            if (module == null || entry == null) throw new IllegalArgumentException("a source needs a module and an entry");
        }
    }

    /**
     * The workbench program as a RAPID module named {@code name}: for a program imported from
     * RAPID, the imported module with the edits spliced in ({@link #spliced}); otherwise the
     * module {@link #toRapid(WorkbenchModel, List, String)} writes.
     */
    public static RapidModule toRapid(WorkbenchModel m, String name) {
        RapidModule own = toRapid(m, m.program(), name);
        Optional<Source> src = m.programSource();
        return src.isPresent() ? spliced(src.get(), own, m.program(), name) : own;
    }

    /**
     * The RAPID text of {@code module} (the model's program, {@link #toRapid(WorkbenchModel, String)}):
     * an imported program as its tree (what was not edited comes out byte for byte as read), a
     * program taught here through {@link RapidWriter} (file precision, valid unique names).
     */
    public static org.robopro.programs.rapid.RapidExport write(WorkbenchModel m, RapidModule module) {
        return m.programSource().isPresent()
                ? new org.robopro.programs.rapid.RapidExport(org.robopro.programs.rapid.RapidAstWriter.write(module.tree()), List.of())
                : RapidWriter.export(module);
    }

    /** The model's targets, tool and work objects with the motions of {@code program} as PROC main (kept statements left out). */
    public static RapidModule toRapid(WorkbenchModel m, List<Instruction> program, String name) {
        program = program.stream().filter(i -> i.type().motion()).toList();
        Tool tool = m.tool();
        Pose worldTbase = m.worldTbase();
        RobotKinematics k = m.kinematics();
        RapidModule.Builder b = RapidModule.builder(name);
        b.comment(" Written by the robopro workbench for " + m.robot().displayName()
                + "; robtargets in their work objects, world = robot base");
        b.pers(tool.name(), toolData(tool));
        Map<String, WorkObject> wobjs = new LinkedHashMap<>();
        for (WorkObject w : m.workObjects()) wobjs.put(w.name(), w);
        List<String> declared = new ArrayList<>();
        java.util.Set<String> absJ = new java.util.HashSet<>(), cartesian = new java.util.HashSet<>();
        for (Instruction i : program) {
            (i.type() == Instruction.Type.MOVEABSJ ? absJ : cartesian).add(i.target());
            if (i.via() != null) cartesian.add(i.via());
        }
        for (Target t : m.targets())
            if (!t.wobj().equalsIgnoreCase(Target.WOBJ0) && !declared.contains(t.wobj())) {
                WorkObject w = wobjs.get(t.wobj());
                if (w == null) throw new IllegalStateException("target " + t.name() + " names unknown work object " + t.wobj());
                declared.add(t.wobj());
                b.pers(w.name(), new WObjData(false, true, "", RapidPose.of(worldTbase.inverse().times(w.worldTuser())), RapidPose.IDENTITY));
            }
        for (Target t : m.targets()) {
            if (absJ.contains(t.name()) && !cartesian.contains(t.name())) {
                b.constant(t.name(), jointTarget(t));
                continue;
            }
            Pose worldTuser = t.wobj().equalsIgnoreCase(Target.WOBJ0) ? Pose.IDENTITY : wobjs.get(t.wobj()).worldTuser();
            b.constant(t.name(), RobTarget.of(worldTuser.inverse().times(t.worldTtcp()), confUsed(m, k, t)));
        }
        List<Statement> body = new ArrayList<>();
        for (Instruction i : program) {
            Target to = m.target(i.target()).orElseThrow(() -> new IllegalStateException("program uses unknown target " + i.target()));
            String wobj = to.wobj().equalsIgnoreCase(Target.WOBJ0) ? null : to.wobj();
            Ref<RobTarget> ref = Ref.to(i.target());
            body.add(switch (i.type()) {
                case MOVEJ -> Move.moveJ(ref, speed(i.speedMmPerS()), zone(i.zoneMm()), tool.name(), wobj);
                case MOVEL -> Move.moveL(ref, speed(i.speedMmPerS()), zone(i.zoneMm()), tool.name(), wobj);
                case MOVEC -> Move.moveC(circPoint(m, k, wobjs, i.via(), to.wobj()), ref, speed(i.speedMmPerS()), zone(i.zoneMm()),
                        tool.name(), wobj);
                // A target also reached by Cartesian moves is a robtarget by its name: its joints go inline.
                case MOVEABSJ -> Move.moveAbsJ(cartesian.contains(i.target()) ? Ref.inline(jointTarget(to)) : Ref.to(i.target()),
                        speed(i.speedMmPerS()), zone(i.zoneMm()), tool.name(), wobj);
                case RAPID -> throw new IllegalStateException("kept statements are left out above");
            });
        }
        b.procedure("main", body);
        return b.build();
    }

    /** A target's joints as a jointtarget (six robot axes; a robot with fewer joints writes 0 for the rest). */
    static org.robopro.programs.JointTarget jointTarget(Target t) {
        return org.robopro.programs.JointTarget.of(java.util.Arrays.copyOf(t.qTaught(), 6));
    }

    /**
     * MoveC's circle point: by name when it is in the move's work object; otherwise written
     * inline in that work object (a RAPID move has one \\WObj for both points).
     */
    private static Ref<RobTarget> circPoint(WorkbenchModel m, RobotKinematics k, Map<String, WorkObject> wobjs, String via, String moveWobj) {
        Target v = m.target(via).orElseThrow(() -> new IllegalStateException("program uses unknown target " + via));
        if (v.wobj().equalsIgnoreCase(moveWobj)) return Ref.to(via);
        Pose worldTuser = moveWobj.equalsIgnoreCase(Target.WOBJ0) ? Pose.IDENTITY : wobjs.get(moveWobj).worldTuser();
        return Ref.inline(RobTarget.of(worldTuser.inverse().times(v.worldTtcp()), confUsed(m, k, v)));
    }

    /** Confdata of the IK solution used for {@code t}: the one next to its taught joints; the stored one if none. */
    static ConfData confUsed(WorkbenchModel m, RobotKinematics k, Target t) {
        Pose baseTflange = m.worldTbase().inverse().times(t.worldTtcp()).times(m.tool().flangeTtcp().inverse());
        return k.solveNear(baseTflange, t.qTaught()).map(k::confOf).orElse(t.conf());
    }

    static ToolData toolData(Tool t) {
        return new ToolData(true, RapidPose.of(t.flangeTtcp()),
                new LoadData(t.massKg(), new Vec3(0, 0, Math.max(1e-6, t.bodyLength() / 2)), Quaternion.IDENTITY, 0, 0, 0));
    }

    /** A predefined speeddata when one matches (v500), otherwise written inline. */
    static Ref<SpeedData> speed(double mmPerS) {
        long r = Math.round(mmPerS);
        if (Math.abs(r - mmPerS) < 1e-9) {
            Optional<SpeedData> p = SpeedData.predefined("v" + r);
            if (p.isPresent()) return Ref.to("v" + r);
        }
        return Ref.inline(SpeedData.ofRapid(mmPerS, 500, 5000, 1000));
    }

    /** fine, a predefined zonedata (z10), or inline with the predefined data's proportions. */
    static Ref<ZoneData> zone(double mm) {
        if (mm == 0) return Ref.to("fine");
        long r = Math.round(mm);
        if (Math.abs(r - mm) < 1e-9 && ZoneData.predefined("z" + r).isPresent()) return Ref.to("z" + r);
        return Ref.inline(ZoneData.ofRapid(false, mm, 1.5 * mm, 1.5 * mm, 0.15 * mm, 1.5 * mm, 0.15 * mm));
    }

    /**
     * The imported module with the program's edits: the entry procedure's body is the program
     * (kept statements as written; a motion still linked to its statement as written, unless it
     * has an inline target that moved; other motions as {@code own} writes them), and the
     * robtarget, jointtarget and wobjdata declarations whose values the workbench changed take
     * {@code own}'s values; new ones a rewritten motion names are declared after the module's data. Every other item
     * (tooldata, other data, routines, records, comments) is kept as read.
     */
    static RapidModule spliced(Source src, RapidModule own, List<Instruction> program, String name) {
        // own at the file's precision, as an export writes it: what a changed part is written as.
        RapidModule gen = RapidParser.parse(RapidWriter.export(own).text(), name);
        RapidModule source = src.module();
        RapidAst.Routine genMain = (RapidAst.Routine) gen.tree().items().stream()
                .filter(it -> it instanceof RapidAst.Routine r && r.name().equalsIgnoreCase("main")).findFirst().orElseThrow();
        Map<String, RapidAst.DataDecl> genDecls = new LinkedHashMap<>();
        for (RapidAst.Item it : gen.tree().items())
            if (it instanceof RapidAst.DataDecl d && TARGET_TYPES.contains(d.type().toLowerCase(Locale.ROOT)))
                genDecls.put(d.name().toLowerCase(Locale.ROOT), d);
        // A work object the workbench knows by another name (the cell's, same frame) keeps the module's name.
        Map<String, String> sourceName = new java.util.HashMap<>();
        for (RapidAst.DataDecl g : genDecls.values())
            if (g.type().equalsIgnoreCase("wobjdata") && source.declaration(g.name()).isEmpty())
                for (Declaration d : source.declarations())
                    if (d.value() instanceof WObjData && sameValue(gen.declaration(g.name()), Optional.of(d)))
                        sourceName.putIfAbsent(g.name().toLowerCase(Locale.ROOT), d.name());
        List<RapidAst.Stmt> body = new ArrayList<>();
        java.util.Set<String> named = new java.util.HashSet<>(); // data the rewritten statements name
        int k = 0;
        for (Instruction i : program) {
            if (!i.type().motion()) { body.add(i.statement()); continue; }
            RapidAst.Stmt fresh = genMain.body().get(k++);
            if (i.statement() != null && inlineUnchanged(source, i, gen)) body.add(i.statement());
            else {
                if (fresh instanceof RapidAst.Call c) {
                    List<RapidAst.Arg> args = new ArrayList<>();
                    for (RapidAst.Arg a : c.args()) {
                        if (a.value() instanceof RapidAst.Name n) {
                            String to = sourceName.getOrDefault(n.name().toLowerCase(Locale.ROOT), n.name());
                            named.add(to.toLowerCase(Locale.ROOT));
                            a = new RapidAst.Arg(a.kind(), a.name(), new RapidAst.Name(to));
                        }
                        args.add(a);
                    }
                    fresh = new RapidAst.Call(c.name(), c.lateBinding(), args);
                }
                body.add(fresh);
            }
        }
        List<RapidAst.Item> items = new ArrayList<>();
        java.util.Set<String> declared = new java.util.HashSet<>();
        int lastData = -1;
        for (RapidAst.Item it : source.tree().items()) {
            if (it instanceof RapidAst.DataDecl d) {
                String key = d.name().toLowerCase(Locale.ROOT);
                declared.add(key);
                RapidAst.DataDecl g = genDecls.get(key);
                boolean changed = g != null && d.dims().isEmpty() && g.type().equalsIgnoreCase(d.type())
                        && !sameValue(source.declaration(d.name()), gen.declaration(d.name()));
                items.add(changed ? new RapidAst.DataDecl(d.scope(), d.storage(), d.type(), d.name(), d.dims(), g.init()) : d);
                lastData = items.size() - 1;
            } else if (it instanceof RapidAst.Routine r && r.name().equalsIgnoreCase(src.entry()) && r.kind() == RapidAst.RoutineKind.PROC) {
                items.add(new RapidAst.Routine(r.local(), r.kind(), r.returnType(), r.name(), r.params(), body, r.backward(),
                        r.errorNumbers(), r.error(), r.undo()));
            } else items.add(it);
        }
        List<RapidAst.Item> added = new ArrayList<>();
        for (Map.Entry<String, RapidAst.DataDecl> e : genDecls.entrySet())
            if (!declared.contains(e.getKey()) && named.contains(e.getKey())) added.add(e.getValue());
        items.addAll(lastData + 1, added);
        return RapidModule.of(new RapidAst.Module(name, source.tree().options(), items));
    }

    /** Data the workbench edits (targets and work objects); tooldata and everything else stays as read. */
    private static final java.util.Set<String> TARGET_TYPES = java.util.Set.of("robtarget", "jointtarget", "wobjdata");

    /** Poses and joints closer than this (m, rad) are unchanged by a write at the file's precision. */
    private static final double UNCHANGED = 1e-6;

    private static boolean sameValue(Optional<Declaration> a, Optional<Declaration> b) {
        if (a.isEmpty() || b.isEmpty()) return a.isEmpty() == b.isEmpty();
        return sameValue(a.get().value(), b.get().value());
    }

    private static boolean sameValue(RapidValue a, RapidValue b) {
        if (a instanceof RobTarget x && b instanceof RobTarget y)
            return samePose(x.pose(), y.pose(), UNCHANGED) && x.robconf().equals(y.robconf());
        if (a instanceof org.robopro.programs.JointTarget x && b instanceof org.robopro.programs.JointTarget y) {
            for (int k = 0; k < 6; k++) if (Math.abs(x.robax(k) - y.robax(k)) > UNCHANGED) return false;
            return true;
        }
        if (a instanceof WObjData x && b instanceof WObjData y)
            return x.robhold() == y.robhold() && samePose(x.uframe().toPose().times(x.oframe().toPose()),
                    y.uframe().toPose().times(y.oframe().toPose()), UNCHANGED);
        return a.equals(b);
    }

    /** A linked motion's inline targets (if any) still hold the workbench's targets. */
    private static boolean inlineUnchanged(RapidModule source, Instruction i, RapidModule gen) {
        Move mv = null;
        for (Procedure p : source.procedures())
            for (Statement st : p.body())
                if (st instanceof Move m && source.node(m).orElse(null) == i.statement()) mv = m;
        if (mv == null) return !(i.statement() instanceof RapidAst.Call c) || c.args().stream().noneMatch(a -> a.value() instanceof RapidAst.Aggregate);
        if (mv.toPoint() instanceof Ref.Inline<?> to && !sameInline(to.value(), gen, i.target())) return false;
        return !(mv.circPoint().orElse(null) instanceof Ref.Inline<?> c) || sameInline(c.value(), gen, i.via());
    }

    private static boolean sameInline(RapidValue v, RapidModule gen, String target) {
        return target != null && gen.declaration(target).map(d -> sameValue(v, d.value())).orElse(false);
    }

    /** The program read from a RAPID module, in workbench terms; {@code source}: the module and procedure it came from. */
    public record Imported(String moduleName, Tool tool, List<WorkObject> workObjects, List<Target> targets,
                           List<Instruction> program, List<String> notes, Source source) {
        public Imported {
            workObjects = List.copyOf(workObjects);
            targets = List.copyOf(targets);
            program = List.copyOf(program);
            notes = List.copyOf(notes);
        }
    }

    /**
     * Reads procedure {@code entry} of a parsed module into workbench targets and instructions
     * for the model's robot, placement and work objects. Interpreter errors (unknown names,
     * unsupported frames) are InputExceptions naming the file, line and column.
     */
    public static Imported fromRapid(ParsedModule parsed, WorkbenchModel m, String entry) {
        return imported(new Source(parsed.module(), entry), MotionInterpreter.of(parsed).run(entry), m);
    }

    /** Like {@link #fromRapid(ParsedModule, WorkbenchModel, String)} for a module not read from a RAPID file. */
    public static Imported fromRapid(RapidModule module, WorkbenchModel m, String entry) {
        return imported(new Source(module, entry), MotionInterpreter.of(module).run(entry), m);
    }

    private static Imported imported(Source src, List<ProgramStep> steps, WorkbenchModel m) {
        String moduleName = src.module().name();
        RapidAst.Routine routine = (RapidAst.Routine) src.module().tree().items().stream()
                .filter(it -> it instanceof RapidAst.Routine r && r.name().equalsIgnoreCase(src.entry())).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("module " + moduleName + " has no procedure " + src.entry()));
        // A motion is an instruction when its statement is one of the entry's own and runs once.
        Map<RapidAst.Stmt, Integer> runs = new java.util.IdentityHashMap<>();
        for (ProgramStep s : steps)
            if (s instanceof MoveStep mv) mv.statement().ifPresent(st -> runs.merge(st, 1, Integer::sum));
        java.util.Set<RapidAst.Stmt> own = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        for (RapidAst.Stmt st : routine.body()) if (runs.getOrDefault(st, 0) == 1) own.add(st);
        Map<RapidAst.Stmt, Instruction> moves = new java.util.IdentityHashMap<>();
        RobotKinematics k = m.kinematics();
        Optional<InverseKinematics> ik = k.kinematicModel().map(InverseKinematics::of);
        Pose worldTbase = m.worldTbase();
        List<String> notes = new ArrayList<>();
        Map<String, WorkObject> wobjs = new LinkedHashMap<>();
        for (WorkObject w : m.workObjects()) wobjs.put(w.name(), w);
        // The cell's targets come first: an imported target equal to one of them is that one.
        Map<String, Target> targets = new LinkedHashMap<>();
        for (Target t : m.targets()) targets.put(t.name(), t);
        Map<String, String> wobjRenamed = new LinkedHashMap<>();
        List<Instruction> program = new ArrayList<>();
        Tool tool = null;
        double[] seed = m.q();
        int fresh = 0;
        int elsewhere = 0;
        for (ProgramStep s : steps) {
            if (!(s instanceof MoveStep mv)) continue; // waits, I/O and process instructions are kept as statements
            if (mv.statement().isEmpty() || !own.contains(mv.statement().get())) { elsewhere++; continue; }
            RapidAst.Stmt stmt = mv.statement().get();
            if (tool == null) {
                Pose tcp = mv.tool().tframe().toPose();
                Tool cur = m.tool();
                tool = cur.name().equalsIgnoreCase(mv.toolName())
                        ? new Tool(cur.name(), tcp, cur.bodyRadius(), cur.bodyLength(), Math.max(0.001, mv.tool().tload().mass()))
                        : new Tool(mv.toolName(), tcp, 0.03, Math.max(0.05, tcp.z() * 0.55), Math.max(0.001, mv.tool().tload().mass()));
            } else if (!tool.name().equalsIgnoreCase(mv.toolName())) {
                notes.add(mv.label() + ": uses tool " + mv.toolName() + "; the workbench mounts one tool (" + tool.name() + ")");
            }
            String wobj = Target.WOBJ0;
            if (!mv.wobjName().equalsIgnoreCase("wobj0")) {
                Pose worldTuser = worldTbase.times(mv.wobj().uframe().toPose()).times(mv.wobj().oframe().toPose());
                wobj = workObject(wobjs, mv.wobjName(), worldTuser, wobjRenamed, notes);
            }
            double speed = Math.max(1e-3, Units.mToMm(mv.speed().vTcp()));
            double zone = mv.zone().finep() ? 0 : Units.mToMm(mv.zone().pzoneTcp());
            if (mv.kind() == Move.Kind.MOVE_ABS_J) {
                double[] q = java.util.Arrays.copyOf(mv.q().orElseThrow(), k.dof());
                Target same = sameJoints(targets, mv.targetName(), q);
                if (same == null) {
                    Pose worldTtcp = worldTbase.times(k.flange(q)).times(mv.flangeTtcp());
                    same = new Target(uniqueName(targets, mv.targetName(), fresh++), worldTtcp, q, k.confOf(q), wobj);
                    targets.put(same.name(), same);
                }
                moves.put(stmt, new Instruction(Instruction.Type.MOVEABSJ, same.name(), speed, zone, null, stmt));
                seed = q;
                continue;
            }
            String via = null;
            if (mv.kind() == Move.Kind.MOVE_C) {
                Pose circTcp = worldTbase.times(mv.baseTtcpCirc().orElseThrow());
                Target c = target(ik, targets, mv.circName().orElse("*"), circTcp, mv.baseTflangeCirc().orElseThrow(),
                        mv.conf().orElseThrow(), seed, wobj, fresh++);
                via = c.name();
                targets.put(via, c);
                seed = c.qTaught();
            }
            Target t = target(ik, targets, mv.targetName(), worldTbase.times(mv.baseTtcp().orElseThrow()),
                    mv.baseTflange().orElseThrow(), mv.conf().orElseThrow(), seed, wobj, fresh++);
            targets.put(t.name(), t);
            seed = t.qTaught();
            Instruction.Type type = switch (mv.kind()) {
                case MOVE_L -> Instruction.Type.MOVEL;
                case MOVE_C -> Instruction.Type.MOVEC;
                default -> Instruction.Type.MOVEJ;
            };
            moves.put(stmt, new Instruction(type, t.name(), speed, zone, via, stmt));
        }
        int kept = 0;
        for (RapidAst.Stmt st : routine.body()) {
            Instruction i = moves.get(st);
            if (i == null) kept++;
            program.add(i != null ? i : Instruction.kept(st));
        }
        if (kept > 0) notes.add(kept + " statement(s) of " + src.entry() + " kept as written (shown read-only)");
        if (elsewhere > 0)
            notes.add(elsewhere + " motion(s) in called routines, loops or branches kept as written: not editable or drawn in the workbench");
        if (tool == null) tool = m.tool();
        return new Imported(moduleName, tool, List.copyOf(wobjs.values()), List.copyOf(targets.values()), program, notes, src);
    }

    /** Poses closer than this (m, rad) are the same target or work object frame. */
    static final double SAME_POSE = 1e-6;

    private static boolean samePose(Pose a, Pose b) { return samePose(a, b, SAME_POSE); }

    private static boolean samePose(Pose a, Pose b, double tol) { return a.distanceTo(b) < tol && a.angleTo(b) < tol; }

    /**
     * The name an imported work object goes by: the cell's work object with the same frame (any
     * name), else its own name (made unique when the cell uses it for another frame).
     */
    private static String workObject(Map<String, WorkObject> wobjs, String name, Pose worldTuser, Map<String, String> renamed,
                                     List<String> notes) {
        for (WorkObject w : wobjs.values()) {
            if (!samePose(w.worldTuser(), worldTuser)) continue;
            if (!w.name().equals(name) && renamed.put(name, w.name()) == null)
                notes.add("work object " + name + " is the cell's " + w.name() + " (same frame)");
            return w.name();
        }
        String n = name;
        for (int i = 2; wobjs.containsKey(n); i++) n = name + "_" + i;
        if (!n.equals(name)) notes.add("work object " + name + " differs from the cell's " + name + ": imported as " + n);
        wobjs.put(n, new WorkObject(n, worldTuser));
        return n;
    }

    /** A known target with these joints: the named one first, else any with the same joints (MoveAbsJ twice to home). */
    private static Target sameJoints(Map<String, Target> targets, String name, double[] q) {
        Target named = targets.get(name);
        if (named != null && sameJoints(named.qTaught(), q)) return named;
        for (Target t : targets.values()) if (sameJoints(t.qTaught(), q)) return t;
        return null;
    }

    private static boolean sameJoints(double[] a, double[] b) {
        if (a.length != b.length) return false;
        for (int i = 0; i < a.length; i++) if (Math.abs(a[i] - b[i]) > SAME_POSE) return false;
        return true;
    }

    /**
     * A target for a robtarget reached at {@code worldTtcp}: a known target with the same pose and
     * work object (the named one first: a target used twice, or imported again), else a new one
     * under its own name (a fresh name when that is taken); joints from IK with the target's
     * confdata (falling back to the solution next to the previous target).
     */
    private static Target target(Optional<InverseKinematics> ik, Map<String, Target> targets, String name,
                                 Pose worldTtcp, Pose baseTflange, ConfData conf, double[] seed, String wobj, int fresh) {
        Target same = targets.get(name);
        if (same != null && samePose(same.worldTtcp(), worldTtcp) && same.wobj().equals(wobj)) return same;
        for (Target t : targets.values()) if (samePose(t.worldTtcp(), worldTtcp) && t.wobj().equals(wobj)) return t;
        double[] q = null;
        if (ik.isPresent()) {
            q = ik.get().solveWithConf(baseTflange, conf).map(IkSolution::q).orElse(null);
            if (q == null) q = ik.get().solveNear(baseTflange, seed).map(IkSolution::q).orElse(null);
        }
        if (q == null) q = seed.clone(); // unreachable: kept, and marked red by the check
        return new Target(uniqueName(targets, name, fresh), worldTtcp, q, conf, wobj);
    }

    private static String uniqueName(Map<String, Target> targets, String wanted, int fresh) {
        if (!"*".equals(wanted) && !targets.containsKey(wanted)) return wanted;
        String base = "*".equals(wanted) ? "pImp" : wanted + "_";
        for (int i = fresh + 1; ; i++) {
            String n = String.format(Locale.ROOT, "%s%d", base, i);
            if (!targets.containsKey(n)) return n;
        }
    }
}
