package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robopro.models.AtomicFiles;
import org.robopro.programs.RapidModule;
import org.robopro.programs.project.ProgramProject;
import org.robopro.programs.rapid.RapidExport;
import org.robopro.programs.RapidWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code robopro program export PROJECT --out FILE.mod}: a program project file (docs/programs.md) as a RAPID module. */
@Command(name = "export", mixinStandardHelpOptions = true, description = "Export a program project (JSON) as a RAPID module.")
public final class ProgramExportCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "PROJECT") Path project;

    @Mixin OutputFileOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        RapidModule m = ProgramProject.read(project);
        RapidExport e = RapidWriter.export(m);
        AtomicFiles.writeString(out.file(), e.text(), out.force());
        for (RapidExport.Rename r : e.renames()) spec.commandLine().getOut().println("renamed " + r);
        spec.commandLine().getOut().printf("wrote %s: module %s, %d declarations, %d procedures%n", out.file(), m.name(),
                m.declarations().size(), m.procedures().size());
        return 0;
    }
}
