package org.robopro.programs.rapid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robopro.programs.AstItem;
import org.robopro.programs.RapidModule;
import org.robopro.programs.rapid.RapidAst.Expr;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;

class RapidAstTest {

    @Test
    void parseWriteParse_fixtures_sameTree() {
        for (String f : List.of("PickPlace.mod", "Palletize.mod", "CellServer.mod", "Conveyor.mod")) {
            RapidAst.Module a = RapidAstParser.parse(RapidParserTest.fixture(f), f).module();
            String text = RapidAstWriter.write(a);
            RapidAst.Module b = RapidAstParser.parse(text, "again.mod").module();
            assertEquals(a, b, f);
            assertEquals(text, RapidAstWriter.write(b), f);
        }
    }

    @Test
    void parse_cellServer_serverConstructsInTree() {
        RapidAst.Module m = RapidAstParser.parse(RapidParserTest.fixture("CellServer.mod"), "CellServer.mod").module();
        RapidAst.Routine main = routine(m, "main");
        // ERROR (LONG_JMP_ALL_ERR, ERR_SOCK_CLOSED): two error numbers, a handler with RETRY/TRYNEXT, an UNDO handler
        assertEquals(List.of(new RapidAst.Name("LONG_JMP_ALL_ERR"), new RapidAst.Name("ERR_SOCK_CLOSED")), main.errorNumbers());
        RapidAst.Test handler = assertInstanceOf(RapidAst.Test.class, main.error().get(0));
        assertEquals(2, handler.cases().get(0).values().size(), "CASE with two values");
        assertInstanceOf(RapidAst.Retry.class, handler.cases().get(0).body().get(1));
        assertInstanceOf(RapidAst.TryNext.class, handler.otherwise().get(0));
        assertInstanceOf(RapidAst.CompactIf.class, main.undo().get(0));
        // PERS without initialiser, array of CONST size, record with an array component
        RapidAst.DataDecl speed = data(m, "cellSpeed");
        assertEquals(RapidAst.Storage.PERS, speed.storage());
        assertEquals(null, speed.init());
        assertEquals(List.of(new RapidAst.Name("MAX_QUEUE")), data(m, "queue").dims());
        // WaitUntil (cond) \PollRate:=.05: a parenthesised first argument, then an optional one
        RapidAst.Call wait = main.body().stream().filter(st -> st instanceof RapidAst.Call c && c.name().equals("WaitUntil"))
                .map(st -> (RapidAst.Call) st).findFirst().orElseThrow();
        assertInstanceOf(RapidAst.Binary.class, wait.args().get(0).value());
        assertEquals(new RapidAst.Arg(RapidAst.ArgKind.OPTIONAL, "PollRate", new RapidAst.Num("0.05")), wait.args().get(1));
        // SocketReceive peer \Str:=request \Time:=WAIT_MAX (optional arguments without commas)
        RapidAst.While loop = main.body().stream().filter(st -> st instanceof RapidAst.While).map(st -> (RapidAst.While) st).findFirst().orElseThrow();
        RapidAst.Call receive = assertInstanceOf(RapidAst.Call.class, loop.body().get(0));
        assertEquals(List.of(RapidAst.Arg.positional(new RapidAst.Name("peer")),
                new RapidAst.Arg(RapidAst.ArgKind.OPTIONAL, "Str", new RapidAst.Name("request")),
                new RapidAst.Arg(RapidAst.ArgKind.OPTIONAL, "Time", new RapidAst.Name("WAIT_MAX"))), receive.args());
        assertEquals(RapidAst.RoutineKind.TRAP, routine(m, "on_timer").kind());
    }

    @Test
    void parse_compactIfWithLabel_refusedAtTheLabel() {
        org.robopro.models.InputException e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> RapidAstParser.parse("MODULE M\n  PROC main()\n    IF TRUE here: WaitTime 1;\n  ENDPROC\nENDMODULE\n", "p.mod"));
        assertEquals(3, e.line());
        assertEquals(13, e.column());
        assertTrue(e.getMessage().contains("compact IF"), e.getMessage());
    }

    @Test
    void parse_callWithParenthesisedCalls_helpfulMessage() {
        org.robopro.models.InputException e = org.junit.jupiter.api.Assertions.assertThrows(org.robopro.models.InputException.class,
                () -> RapidAstParser.parse("MODULE M\n  PROC main()\n    Foo(1, 2);\n  ENDPROC\nENDMODULE\n", "p.mod"));
        assertEquals(3, e.line());
        assertEquals(8, e.column());
        assertTrue(e.getMessage().contains("without parentheses"), e.getMessage());
    }

    private static RapidAst.Routine routine(RapidAst.Module m, String name) {
        return m.items().stream().filter(i -> i instanceof RapidAst.Routine r && r.name().equals(name)).map(i -> (RapidAst.Routine) i)
                .findFirst().orElseThrow();
    }

    private static RapidAst.DataDecl data(RapidAst.Module m, String name) {
        return m.items().stream().filter(i -> i instanceof RapidAst.DataDecl d && d.name().equals(name)).map(i -> (RapidAst.DataDecl) i)
                .findFirst().orElseThrow();
    }

    @Test
    void export_treeBearingFixtures_acceptedByRapidchecker() {
        // Fixtures whose constructs rapidchecker knows (docs/rapid.md lists the valid RAPID it refuses).
        java.util.Map<String, String> files = new java.util.LinkedHashMap<>();
        for (String f : List.of("PickPlace.mod", "Conveyor.mod")) {
            RapidModule m = RapidParser.parse(RapidParserTest.fixture(f), f);
            assertTrue(m.items().stream().anyMatch(i -> i instanceof AstItem) || f.equals("PickPlace.mod"), f + " holds tree items");
            files.put(f, RapidWriter.export(m).text());
        }
        assertTrue(files.get("Conveyor.mod").contains("\\PollRate:=0.05"), files.get("Conveyor.mod"));
        RapidChecker.assertValid(files);
    }

    @Test
    void parse_palletize_typedWhereModelledAndTreeElsewhere() {
        RapidModule m = RapidParser.parse(RapidParserTest.fixture("Palletize.mod"), "Palletize.mod");
        assertTrue(m.declaration("pBase").isPresent(), "literal robtarget is typed");
        assertTrue(m.declaration("pNow").isEmpty(), "robtarget without value stays a tree");
        assertEquals(List.of("main"), m.procedures().stream().map(p -> p.name()).toList());
        long trees = m.items().stream().filter(i -> i instanceof AstItem).count();
        assertEquals(10, trees, "RECORD, ALIAS, 6 data, place, area, onStop minus typed ones");
        assertEquals(RapidAst.Storage.CONST, m.declaration("nMax").orElseThrow().storage());
        String out = RapidWriter.export(m).text();
        assertEquals(out, RapidWriter.export(RapidParser.parse(out, "out.mod")).text());
    }

    @Test
    void parseWriteParse_randomExpressions_sameTree() {
        Random rnd = new Random(42);
        for (int n = 0; n < 2000; n++) {
            Expr e = randomExpr(rnd, 4);
            String text = "MODULE M\n  VAR num x:=" + RapidAstWriter.expr(e) + ";\nENDMODULE\n";
            RapidAst.DataDecl d = (RapidAst.DataDecl) RapidAstParser.parse(text, "r.mod").module().items().get(0);
            assertEquals(e, d.init(), text);
        }
    }

    @Test
    void parseWriteParse_randomModules_sameTree() {
        for (long seed = 1; seed <= 60; seed++) {
            Random rnd = new Random(seed);
            List<RapidAst.Item> items = new ArrayList<>();
            items.add(new RapidAst.DataDecl(RapidAst.Scope.LOCAL, RapidAst.Storage.VAR, "num", "a", List.of(new RapidAst.Num("3")), null));
            items.add(new RapidAst.RecordDecl(false, "rec", List.of(new RapidAst.Field("num", "x"), new RapidAst.CommentLine(" c"))));
            List<RapidAst.Stmt> body = new ArrayList<>();
            for (int k = 0; k < 6; k++) body.add(randomStmt(rnd, 3));
            items.add(new RapidAst.Routine(rnd.nextBoolean(), RapidAst.RoutineKind.PROC, null, "p" + seed,
                    List.of(new RapidAst.Param(false, List.of(new RapidAst.ParamAlt("INOUT", "num", "n", 0))),
                            new RapidAst.Param(true, List.of(new RapidAst.ParamAlt(null, "switch", "s", 0), new RapidAst.ParamAlt(null, "num", "t", 1)))),
                    body, null, rnd.nextBoolean() ? List.of(new RapidAst.Name("ERR_X")) : null, List.of(new RapidAst.Retry()), List.of()));
            RapidAst.Module m = new RapidAst.Module("R" + seed, List.of("SYSMODULE"), items);
            String text = RapidAstWriter.write(m);
            assertEquals(m, RapidAstParser.parse(text, "r.mod").module(), text);
        }
    }

    static RapidAst.Stmt randomStmt(Random rnd, int depth) {
        int k = depth <= 0 ? rnd.nextInt(4) : rnd.nextInt(9);
        return switch (k) {
            case 0 -> new RapidAst.Assign(new RapidAst.Component(new RapidAst.Index(new RapidAst.Name("a"), List.of(randomExpr(rnd, 1))), "x"), randomExpr(rnd, 3));
            case 1 -> new RapidAst.Call("MoveL", null, List.of(new RapidAst.Arg(RapidAst.ArgKind.SWITCH, "Conc", null),
                    RapidAst.Arg.positional(new RapidAst.FuncCall("Offs", List.of(RapidAst.Arg.positional(new RapidAst.Name("p")),
                            RapidAst.Arg.positional(randomExpr(rnd, 2))))), RapidAst.Arg.positional(new RapidAst.Name("v100")),
                    new RapidAst.Arg(RapidAst.ArgKind.OPTIONAL, "V", new RapidAst.Num("80")),
                    new RapidAst.Arg(RapidAst.ArgKind.NAMED, "Zone", new RapidAst.Name("z10")),
                    new RapidAst.Arg(RapidAst.ArgKind.CONDITIONAL, "WObj", new RapidAst.Name("w"))));
            case 2 -> new RapidAst.CommentLine(" note " + rnd.nextInt(9));
            case 3 -> new RapidAst.Call(null, new RapidAst.Binary("+", new RapidAst.Str("proc"), new RapidAst.Name("n")), List.of());
            case 4 -> new RapidAst.If(randomExpr(rnd, 2), stmts(rnd, depth), List.of(new RapidAst.ElseIf(randomExpr(rnd, 2), stmts(rnd, depth))),
                    rnd.nextBoolean() ? stmts(rnd, depth) : null);
            case 5 -> new RapidAst.While(randomExpr(rnd, 2), stmts(rnd, depth));
            case 6 -> new RapidAst.For("i", randomExpr(rnd, 1), randomExpr(rnd, 1), rnd.nextBoolean() ? null : new RapidAst.Num("2"), stmts(rnd, depth));
            case 7 -> new RapidAst.Test(randomExpr(rnd, 1), List.of(new RapidAst.Case(List.of(new RapidAst.Num("1"), new RapidAst.Num("2")), stmts(rnd, depth))),
                    rnd.nextBoolean() ? stmts(rnd, depth) : null);
            default -> new RapidAst.CompactIf(randomExpr(rnd, 2), rnd.nextBoolean() ? new RapidAst.Goto("l1") : new RapidAst.Return(null));
        };
    }

    static List<RapidAst.Stmt> stmts(Random rnd, int depth) {
        List<RapidAst.Stmt> l = new ArrayList<>();
        int n = rnd.nextInt(3);
        for (int k = 0; k < n; k++) l.add(randomStmt(rnd, depth - 1));
        if (rnd.nextInt(4) == 0) l.add(new RapidAst.Label("l1"));
        return l;
    }

    static final String[] OPS = {"OR", "XOR", "AND", "=", "<>", "<", ">", "<=", ">=", "+", "-", "*", "/", "DIV", "MOD"};

    static Expr randomExpr(Random rnd, int depth) {
        int k = depth <= 0 ? rnd.nextInt(5) : rnd.nextInt(10);
        return switch (k) {
            case 0 -> new RapidAst.Num(List.of("1", "2.5", "0x1F", "1E+09", ".5", "0b101", "3E-07").get(rnd.nextInt(7)));
            case 1 -> new RapidAst.Name(List.of("a", "b", "nCount").get(rnd.nextInt(3)));
            case 2 -> new RapidAst.Str(List.of("", "x\\22y", "a\\\\b").get(rnd.nextInt(3)));
            case 3 -> new RapidAst.Bool(rnd.nextBoolean());
            case 4 -> new RapidAst.Component(new RapidAst.Name("p"), "trans");
            case 5 -> new RapidAst.Unary(List.of("-", "+", "NOT").get(rnd.nextInt(3)), randomExpr(rnd, depth - 1));
            case 6 -> new RapidAst.Aggregate(List.of(randomExpr(rnd, depth - 1), randomExpr(rnd, depth - 1)));
            case 7 -> new RapidAst.FuncCall("F", List.of(RapidAst.Arg.positional(randomExpr(rnd, depth - 1)),
                    new RapidAst.Arg(RapidAst.ArgKind.OPTIONAL, "D", randomExpr(rnd, depth - 1))));
            default -> new RapidAst.Binary(OPS[rnd.nextInt(OPS.length)], randomExpr(rnd, depth - 1), randomExpr(rnd, depth - 1));
        };
    }

    @Test
    void parse_hexBinaryOctal_values() {
        assertEquals(31, new RapidAst.Num("0x1F").value());
        assertEquals(5, new RapidAst.Num("0b101").value());
        assertEquals(15, new RapidAst.Num("0o17").value());
        assertInstanceOf(RapidAst.Num.class, ((RapidAst.DataDecl) RapidAstParser.parse("MODULE M\n VAR num a:=0o17;\nENDMODULE", "m")
                .module().items().get(0)).init());
    }
}
