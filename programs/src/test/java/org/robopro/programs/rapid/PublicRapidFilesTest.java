package org.robopro.programs.rapid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.robopro.models.InputException;
import org.robopro.programs.JointTarget;
import org.robopro.programs.sim.MotionInterpreter;
import org.robopro.programs.RapidParser;
import org.robopro.programs.RapidWriter;
import org.robopro.programs.ParsedModule;

/**
 * A local check on public RAPID sources (open_abb, abb_driver), which are not committed: set
 * {@code ROBOPRO_PUBLIC_RAPID} to a folder of .mod/.sys files. Each file must parse (tree and
 * typed model) and round-trip (parse, write, parse gives an equal tree); running main either
 * ends or stops with a located "not simulated" / "simulation stopped" message. Skipped without
 * the variable.
 */
class PublicRapidFilesTest {

    @Test
    void publicFiles_parseRoundTripSimulate_noFailure() throws IOException {
        String dir = System.getenv("ROBOPRO_PUBLIC_RAPID");
        assumeTrue(dir != null && !dir.isBlank(), "ROBOPRO_PUBLIC_RAPID not set");
        List<Path> files;
        try (Stream<Path> s = Files.list(Path.of(dir))) {
            files = s.filter(p -> p.toString().endsWith(".mod") || p.toString().endsWith(".sys")).sorted().toList();
        }
        List<String> failures = new ArrayList<>();
        for (Path f : files) {
            String name = f.getFileName().toString();
            String text = Files.readString(f, StandardCharsets.UTF_8);
            try {
                ParsedAst ast = RapidAstParser.parse(text, name);
                String written = RapidAstWriter.write(ast.module());
                RapidAst.Module again = RapidAstParser.parse(written, name + "(written)").module();
                if (!ast.module().equals(again)) failures.add(name + ": round trip changed the tree");
                ParsedModule typed = RapidParser.parseDetailed(text, name);
                String exported = RapidWriter.export(typed.module()).text();
                String again2 = RapidWriter.export(RapidParser.parse(exported, name + "(exported)")).text();
                if (!exported.equals(again2)) failures.add(name + ": typed export is not stable");
                String outcome = "no main";
                if (ast.module().items().stream().anyMatch(it -> it instanceof RapidAst.Routine r && r.name().equalsIgnoreCase("main"))) {
                    try {
                        // the folder's other modules are the task's other modules (data, routines, records)
                        List<ParsedModule> others = files.stream().filter(o -> !o.equals(f)).map(PublicRapidFilesTest::parsed).toList();
                        int n = MotionInterpreter.ofTask(typed, others).withMaxStatements(20_000)
                                .withStartJoints(JointTarget.of(0, 0, 0, 0, 0, 0)).run("main").size();
                        outcome = "ran, " + n + " steps";
                    } catch (InputException stopped) {
                        outcome = stopped.getMessage();
                    }
                }
                long trees = typed.module().items().stream().filter(it -> it instanceof org.robopro.programs.AstItem).count();
                System.out.println("[public] " + name + ": parse OK, round trip OK, typed items "
                        + (typed.module().items().size() - trees) + ", tree items " + trees + ", main: " + outcome);
            } catch (InputException | IllegalArgumentException | IllegalStateException e) {
                failures.add(name + ": " + e);
            }
        }
        assertEquals(List.of(), failures);
    }

    private static ParsedModule parsed(Path p) {
        try {
            return RapidParser.parseDetailed(Files.readString(p, StandardCharsets.UTF_8), p.getFileName().toString());
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
