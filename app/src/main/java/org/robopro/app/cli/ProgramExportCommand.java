package org.robopro.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robopro.app.workbench.ProjectStore;
import org.robopro.app.workbench.WorkbenchSession;
import org.robopro.app.workbench.model.ProgramModule;
import org.robopro.app.workbench.model.ProjectData;
import org.robopro.app.workbench.model.WorkbenchModel;
import org.robopro.models.AtomicFiles;
import org.robopro.models.TextFiles;
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

/**
 * {@code robopro program export PROJECT --out FILE.mod}: a workbench project's program
 * (docs/project-file.md) as the RAPID module the workbench exports, or a program file of the
 * former "robopro-program" format (docs/programs.md) as the module it describes.
 */
@Command(name = "export", mixinStandardHelpOptions = true, description = "Export a project's program (JSON) as a RAPID module.")
public final class ProgramExportCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "PROJECT") Path project;

    @Mixin OutputFileOptions out;

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        String text = TextFiles.readUtf8(project);
        RapidModule m;
        RapidExport e;
        if (ProjectStore.isProgramFile(text, project.toString())) {
            m = ProgramProject.parse(text, project.toString());
            e = RapidWriter.export(m);
        } else {
            ProjectData data = ProjectStore.parse(text, project.toString(), project.toAbsolutePath().getParent());
            WorkbenchModel model = new WorkbenchModel(data.robotRef(), data.robot());
            model.load(data);
            m = ProgramModule.toRapid(model, WorkbenchSession.moduleName(out.file()));
            e = ProgramModule.write(model, m);
        }
        AtomicFiles.writeString(out.file(), e.text(), out.force());
        for (RapidExport.Rename r : e.renames()) spec.commandLine().getOut().println("renamed " + r);
        spec.commandLine().getOut().printf("wrote %s: module %s, %d declarations, %d procedures%n", out.file(), m.name(),
                m.declarations().size(), m.procedures().size());
        return 0;
    }
}
