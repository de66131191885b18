package org.robopro.programs.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robopro.kinematics.Pose;
import org.robopro.models.InputException;
import org.robopro.programs.Declaration;
import org.robopro.programs.JointTarget;
import org.robopro.programs.Move;
import org.robopro.programs.ProcCall;
import org.robopro.programs.Procedure;
import org.robopro.programs.RapidModule;
import org.robopro.programs.RapidValue;
import org.robopro.programs.Ref;
import org.robopro.programs.RobTarget;
import org.robopro.programs.SpeedData;
import org.robopro.programs.Statement;
import org.robopro.programs.ToolData;
import org.robopro.programs.WObjData;
import org.robopro.programs.WaitTime;
import org.robopro.programs.ZoneData;
import org.robopro.programs.rapid.ParsedModule;
import org.robopro.programs.rapid.SourcePos;

/**
 * Runs a module's procedure the way the controller would step through it, without a robot:
 * follows procedure calls, looks up every target, tool, work object, speed and zone (the module
 * first, then library modules, then RAPID's predefined data) and yields {@link ProgramStep}s
 * with poses in base coordinates and SI speeds. Unknown names, unsupported frames and runaway
 * recursion are {@link InputException}s naming the statement. Thread-safe (immutable).
 */
public final class MotionInterpreter {
    /** Procedure calls nested deeper than this are taken as runaway recursion. */
    public static final int MAX_CALL_DEPTH = 32;
    /** Runs producing more steps than this are refused (nested calls can multiply). */
    public static final int MAX_STEPS = 1_000_000;

    private final RapidModule module;
    private final List<RapidModule> libraries;
    private final String file;
    private final Map<Statement, SourcePos> positions;

    private MotionInterpreter(RapidModule module, List<RapidModule> libraries, String file, Map<Statement, SourcePos> positions) {
        this.module = module;
        this.libraries = List.copyOf(libraries);
        this.file = file;
        this.positions = positions;
    }

    /** An interpreter of {@code module}; {@code libraries} provide data declared elsewhere (e.g. tools in user.sys). */
    public static MotionInterpreter of(RapidModule module, RapidModule... libraries) {
        return new MotionInterpreter(module, List.of(libraries), module.name(), Collections.emptyMap());
    }

    /** An interpreter of a parsed file: errors name the file, line and column. */
    public static MotionInterpreter of(ParsedModule parsed, RapidModule... libraries) {
        IdentityHashMap<Statement, SourcePos> pos = new IdentityHashMap<>();
        for (Procedure p : parsed.module().procedures())
            for (Statement s : p.body()) parsed.position(s).ifPresent(sp -> pos.put(s, sp));
        return new MotionInterpreter(parsed.module(), List.of(libraries), parsed.file(), pos);
    }

    /** The steps of running {@code main}. */
    public List<ProgramStep> run() { return run("main"); }

    /** The steps of running procedure {@code entry}. */
    public List<ProgramStep> run(String entry) {
        Procedure p = findProcedure(entry).orElseThrow(() -> new InputException(file, 0, 0, entry, "no procedure " + entry + " in module " + module.name()));
        List<ProgramStep> out = new ArrayList<>();
        runProc(p, 0, out);
        return out;
    }

    /** Only the motions of running {@code entry}. */
    public List<MoveStep> moves(String entry) {
        List<MoveStep> out = new ArrayList<>();
        for (ProgramStep s : run(entry)) if (s instanceof MoveStep m) out.add(m);
        return out;
    }

    private Optional<Procedure> findProcedure(String n) {
        Optional<Procedure> p = module.procedure(n);
        if (p.isPresent()) return p;
        for (RapidModule lib : libraries) {
            p = lib.procedure(n);
            if (p.isPresent()) return p;
        }
        return Optional.empty();
    }

    private void runProc(Procedure p, int depth, List<ProgramStep> out) {
        List<Statement> body = p.body();
        for (int k = 0; k < body.size(); k++) {
            Statement s = body.get(k);
            if (out.size() >= MAX_STEPS) throw error(s, p.name(), "program runs more than " + MAX_STEPS + " steps");
            if (s instanceof Move m) out.add(move(p.name(), k, m));
            else if (s instanceof WaitTime w) out.add(new WaitStep(p.name(), k, Optional.ofNullable(positions.get(s)), w.seconds()));
            else if (s instanceof ProcCall c) {
                if (depth + 1 > MAX_CALL_DEPTH) throw error(s, p.name(), "procedure calls nested deeper than " + MAX_CALL_DEPTH + " (recursion?)");
                Procedure callee = findProcedure(c.procedure())
                        .orElseThrow(() -> error(s, p.name(), "unknown procedure '" + c.procedure() + "'"));
                runProc(callee, depth + 1, out);
            }
        }
    }

    private MoveStep move(String proc, int index, Move m) {
        ToolData tool = lookup(m.tool(), "tooldata", ToolData.class, m, proc);
        String wobjName = m.wobjName();
        WObjData wobj = lookup(wobjName, "wobjdata", WObjData.class, m, proc);
        SpeedData speed = resolve(m.speed(), "speeddata", SpeedData.class, m, proc);
        if (m.v().isPresent()) speed = new SpeedData(m.v().getAsDouble(), speed.vOri(), speed.vLeax(), speed.vReax());
        ZoneData zone = resolve(m.zone(), "zonedata", ZoneData.class, m, proc);
        if (m.z().isPresent())
            zone = new ZoneData(zone.finep(), m.z().getAsDouble(), Math.max(zone.pzoneOri(), m.z().getAsDouble()),
                    Math.max(zone.pzoneEax(), m.z().getAsDouble()), zone.zoneOri(), zone.zoneLeax(), zone.zoneReax());
        Pose flangeTtcp = tool.tframe().toPose();
        Optional<SourcePos> src = Optional.ofNullable(positions.get(m));
        if (m.kind() == Move.Kind.MOVE_ABS_J) {
            JointTarget jt = resolve(m.toPoint(), "jointtarget", JointTarget.class, m, proc);
            return new MoveStep(proc, index, src, m.kind(), m.toPoint().label(), Optional.empty(), Optional.empty(), Optional.empty(),
                    Optional.empty(), Optional.empty(), Optional.empty(), Optional.of(jt.robax()), speed, m.t(), zone,
                    m.tool(), tool, wobjName, wobj, flangeTtcp);
        }
        RobTarget to = resolve(m.toPoint(), "robtarget", RobTarget.class, m, proc);
        Pose[] toPoses = basePoses(to, tool, wobj, m, proc);
        Optional<Pose> circFlange = Optional.empty(), circTcp = Optional.empty();
        Optional<String> circName = Optional.empty();
        if (m.circPoint().isPresent()) {
            RobTarget c = resolve(m.circPoint().get(), "robtarget", RobTarget.class, m, proc);
            Pose[] cp = basePoses(c, tool, wobj, m, proc);
            circFlange = Optional.of(cp[0]);
            circTcp = Optional.of(cp[1]);
            circName = Optional.of(m.circPoint().get().label());
        }
        return new MoveStep(proc, index, src, m.kind(), m.toPoint().label(), circName, Optional.of(toPoses[0]), Optional.of(toPoses[1]),
                circFlange, circTcp, Optional.of(to.robconf()), Optional.empty(), speed, m.t(), zone, m.tool(), tool, wobjName, wobj,
                flangeTtcp);
    }

    /**
     * {baseTflange, baseTtcp} of a robtarget. Robot-held tool: baseTtcp = uframe oframe objTtarget,
     * baseTflange = baseTtcp tframe^-1. Stationary tool with a robot-held work object: the target
     * frame meets the tool frame, baseTflange = worldTtool objTtarget^-1 (uframe oframe)^-1.
     */
    private Pose[] basePoses(RobTarget t, ToolData tool, WObjData wobj, Move m, String proc) {
        if (!wobj.ufprog() || !wobj.ufmec().isEmpty())
            throw error(m, proc, "work objects moved by a mechanical unit (ufprog FALSE or ufmec \"" + wobj.ufmec() + "\") are not supported");
        Pose objT = t.pose();
        Pose userTobj = wobj.uframe().toPose().times(wobj.oframe().toPose());
        Pose tframe = tool.tframe().toPose();
        if (tool.robhold() && !wobj.robhold()) {
            Pose baseTtcp = userTobj.times(objT);
            return new Pose[] {baseTtcp.times(tframe.inverse()), baseTtcp};
        }
        if (!tool.robhold() && wobj.robhold()) {
            Pose baseTflange = tframe.times(objT.inverse()).times(userTobj.inverse());
            return new Pose[] {baseTflange, tframe};
        }
        throw error(m, proc, tool.robhold() ? "tool and work object are both held by the robot" : "neither the tool nor the work object is held by the robot");
    }

    private <T extends RapidValue> T resolve(Ref<?> r, String type, Class<T> cls, Move m, String proc) {
        if (r instanceof Ref.Inline<?> in) {
            if (!cls.isInstance(in.value())) throw error(m, proc, "a " + type + " is needed, found a " + in.value().rapidType());
            return cls.cast(in.value());
        }
        return lookup(((Ref.Named<?>) r).name(), type, cls, m, proc);
    }

    private <T extends RapidValue> T lookup(String name, String type, Class<T> cls, Move m, String proc) {
        Optional<Declaration> d = module.declaration(name);
        for (int k = 0; d.isEmpty() && k < libraries.size(); k++) d = libraries.get(k).declaration(name);
        if (d.isPresent()) {
            if (!cls.isInstance(d.get().value()))
                throw error(m, proc, "'" + name + "' is a " + d.get().rapidType() + ", a " + type + " is needed");
            return cls.cast(d.get().value());
        }
        RapidValue pre = predefined(name);
        if (cls.isInstance(pre)) return cls.cast(pre);
        throw error(m, proc, "unknown " + type + " '" + name + "'");
    }

    private static RapidValue predefined(String name) {
        String k = name.toLowerCase(Locale.ROOT);
        if (k.equals("tool0")) return ToolData.TOOL0;
        if (k.equals("wobj0")) return WObjData.WOBJ0;
        if (k.equals("load0")) return org.robopro.programs.LoadData.LOAD0;
        Optional<SpeedData> s = SpeedData.predefined(k);
        if (s.isPresent()) return s.get();
        return ZoneData.predefined(k).orElse(null);
    }

    private InputException error(Statement s, String proc, String problem) {
        SourcePos p = positions.get(s);
        return p == null ? new InputException(file, 0, 0, proc, problem) : new InputException(p.file(), p.line(), p.column(), proc, problem);
    }
}
