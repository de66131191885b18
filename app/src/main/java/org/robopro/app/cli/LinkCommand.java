package org.robopro.app.cli;

import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.robopro.calibration.measurement.Measurement;
import org.robopro.calibration.measurement.MeasurementJournal;
import org.robopro.calibration.measurement.MeasurementSet;
import org.robopro.comms.CommandInvoker;
import org.robopro.comms.MeasurementCampaign;
import org.robopro.comms.Commands;
import org.robopro.comms.CommsException;
import org.robopro.comms.ControllerStatus;
import org.robopro.comms.MotionResult;
import org.robopro.comms.ProgramInfo;
import org.robopro.comms.client.ProtocolClient;
import org.robopro.comms.client.RequestChannel;
import org.robopro.comms.client.SerialRequestChannel;
import org.robopro.comms.client.TcpRequestChannel;
import org.robopro.comms.protocol.Checksums;
import org.robopro.comms.protocol.OpenAbb;
import org.robopro.kinematics.KinematicModel;
import org.robopro.kinematics.Pose;
import org.robopro.kinematics.Units;
import org.robopro.models.AtomicFiles;
import org.robopro.models.JointType;
import org.robopro.models.RobotDescription;
import org.robopro.models.Vec3;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import org.robopro.models.RobotLibrary;

/**
 * {@code robopro link --tcp HOST:PORT | --serial DEVICE COMMAND [ARGS]}: one command to a
 * controller (a real one running open_abb's SERVER.mod, or robopro's simulator). Exit codes:
 * 0 done, 2 bad arguments, 3 link failure or no answer, 4 the controller refused.
 */
@Command(name = "link", mixinStandardHelpOptions = true,
        description = "Send one command to a robot controller.%n"
                + "COMMAND: ping | joints | pose | move J1..J6 (deg) | movel X Y Z Q1 Q2 Q3 Q4 (mm) | download FILE"
                + " | upload NAME | list | run NAME | stop | status | measure | campaign --poses N --out FILE")
public final class LinkCommand implements Callable<Integer> {
    static final class Where {
        @Option(names = "--tcp", paramLabel = "HOST:PORT", description = "controller's open_abb server") String tcp;
        @Option(names = "--serial", paramLabel = "DEVICE", description = "serial device of the controller link") String serial;
    }

    @ArgGroup(exclusive = true, multiplicity = "1") Where where;

    @Option(names = "--baud", defaultValue = "115200", description = "serial speed (default ${DEFAULT-VALUE})") int baud;

    @Option(names = "--timeout-ms", defaultValue = "5000", description = "reply timeout per request (default ${DEFAULT-VALUE})") long timeoutMs;

    @Option(names = "--name", description = "program name on the controller (download; default: the file name)") String name;

    @Option(names = "--out", paramLabel = "FILE", description = "upload: write the program to FILE instead of printing it; campaign: the measurement file") Path out;

    @Option(names = "--force", description = "upload, campaign: replace FILE if it exists") boolean force;

    @Option(names = "--poses", defaultValue = "150", description = "campaign: number of poses (default ${DEFAULT-VALUE})") int poses;

    @Option(names = "--seed", defaultValue = "1", description = "campaign: seed of the pose choice (default ${DEFAULT-VALUE})") long seed;

    @Option(names = "--robot", paramLabel = "ROBOT", description = "campaign: robot name or file (default: the robot the controller reports)") String robot;

    @Option(names = "--resume", description = "campaign: continue the interrupted campaign kept in FILE.journal") boolean resume;

    @Parameters(index = "0", paramLabel = "COMMAND") String command;

    @Parameters(index = "1..*", paramLabel = "ARGS") List<String> args = new ArrayList<>();

    @Spec CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (timeoutMs <= 0) throw new IllegalArgumentException("--timeout-ms must be > 0");
        RequestChannel channel = where.tcp != null ? TcpRequestChannel.parse(where.tcp) : SerialRequestChannel.open(where.serial, baud);
        PrintWriter o = spec.commandLine().getOut();
        try (ProtocolClient client = new ProtocolClient(channel);
             CommandInvoker inv = new CommandInvoker(client, CommandInvoker.Options.DEFAULT.withReplyTimeout(Duration.ofMillis(timeoutMs)))) {
            run(inv, client, o);
            o.flush();
            return 0;
        } catch (CommsException.Refused e) {
            spec.commandLine().getErr().println("robopro: controller refused: " + e.getMessage());
            return 4;
        } catch (CommsException e) {
            spec.commandLine().getErr().println("robopro: " + e.getMessage());
            return 3;
        }
    }

    private void expectArgs(int n, String usage) {
        if (args.size() != n) throw new IllegalArgumentException(command + " takes " + n + " argument" + (n == 1 ? "" : "s") + ": " + usage);
    }

    private double[] numbers(String what) {
        double[] v = new double[args.size()];
        for (int i = 0; i < v.length; i++) {
            try {
                v[i] = Double.parseDouble(args.get(i));
                if (!Double.isFinite(v[i])) throw new NumberFormatException();
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(what + " argument " + (i + 1) + " '" + args.get(i) + "' is not a finite number");
            }
        }
        return v;
    }

    private void run(CommandInvoker inv, ProtocolClient client, PrintWriter o) throws Exception {
        switch (command.toLowerCase(Locale.ROOT)) {
            case "ping" -> { expectArgs(0, "ping"); inv.execute(Commands.ping()); o.println("ok"); }
            case "joints" -> {
                expectArgs(0, "joints");
                double[] q = inv.execute(Commands.readJoints());
                StringBuilder sb = new StringBuilder();
                for (double v : q) sb.append(sb.length() == 0 ? "" : " ").append(OpenAbb.num(Units.radToDeg(v), 4));
                o.println(sb + "  (deg)");
            }
            case "pose" -> { expectArgs(0, "pose"); o.println(pose(inv.execute(Commands.readPose()))); }
            case "move" -> {
                expectArgs(6, "move J1 J2 J3 J4 J5 J6 (degrees)");
                MotionResult m = inv.execute(Commands.moveJoints(Units.degToRad(numbers("move"))));
                o.println("moved" + (Double.isNaN(m.motionTimeS()) ? "" : String.format(Locale.ROOT, " in %.3f s", m.motionTimeS())));
            }
            case "movel" -> {
                expectArgs(7, "movel X Y Z Q1 Q2 Q3 Q4 (mm, unit quaternion with Q1 the scalar)");
                double[] v = numbers("movel");
                Pose target = Pose.fromQuaternion(v[3], v[4], v[5], v[6], Units.mmToM(v[0]), Units.mmToM(v[1]), Units.mmToM(v[2]));
                MotionResult m = inv.execute(Commands.moveLinear(target));
                o.println("moved" + (Double.isNaN(m.motionTimeS()) ? "" : String.format(Locale.ROOT, " in %.3f s", m.motionTimeS())));
            }
            case "download" -> {
                expectArgs(1, "download FILE");
                Path file = Path.of(args.get(0));
                if (!Files.isRegularFile(file)) throw new IllegalArgumentException("no such file: " + file);
                String n = name != null ? name : file.getFileName().toString().replaceFirst("\\.[^.]*$", "");
                if (!OpenAbb.validProgramName(n))
                    throw new IllegalArgumentException("program name '" + n + "' is not a RAPID identifier (1-32 letters, digits, _); give --name");
                ProgramInfo p = inv.execute(Commands.downloadProgram(n, Files.readAllBytes(file)));
                o.println("stored " + p.name() + ": " + p.length() + " bytes, crc32 " + Checksums.hex(p.crc32()) + " (verified)");
            }
            case "upload" -> {
                expectArgs(1, "upload NAME");
                byte[] text = inv.execute(Commands.uploadProgram(args.get(0)));
                if (out != null) {
                    AtomicFiles.write(out, text, force);
                    o.println("wrote " + out + ": " + text.length + " bytes, crc32 " + Checksums.hex(Checksums.crc32(text)) + " (verified)");
                } else {
                    o.print(new String(text, StandardCharsets.UTF_8));
                }
            }
            case "list" -> {
                expectArgs(0, "list");
                for (ProgramInfo p : inv.execute(Commands.listPrograms()))
                    o.println(p.name() + " " + p.length() + " bytes crc32 " + Checksums.hex(p.crc32()));
            }
            case "run" -> {
                expectArgs(1, "run NAME");
                inv.execute(Commands.startProgram(args.get(0)));
                ControllerStatus st;
                do {
                    Thread.sleep(50);
                    st = inv.execute(Commands.readStatus());
                } while (st.state() == ControllerStatus.State.RUNNING);
                o.println(status(st));
                if (st.state() == ControllerStatus.State.ERROR)
                    throw new CommsException.Refused(st.lastError() == null ? org.robopro.comms.ErrorCode.PROGRAM_RUNTIME : st.lastError(),
                            String.valueOf(st.lastErrorMessage()));
            }
            case "stop" -> { expectArgs(0, "stop"); inv.execute(Commands.stopProgram()); o.println("stopped"); }
            case "status" -> { expectArgs(0, "status"); o.println(status(inv.execute(Commands.readStatus()))); }
            case "measure" -> {
                expectArgs(0, "measure");
                Vec3 p = inv.execute(Commands.measure());
                o.println(OpenAbb.num(Units.mToMm(p.x()), 4) + " " + OpenAbb.num(Units.mToMm(p.y()), 4) + " "
                        + OpenAbb.num(Units.mToMm(p.z()), 4) + "  (mm, tracker frame)");
            }
            case "campaign" -> campaign(inv, client, o);
            default -> throw new IllegalArgumentException("unknown link command '" + command
                    + "'; use ping, joints, pose, move, movel, download, upload, list, run, stop, status, measure, campaign");
        }
    }

    /** A calibration campaign: poses by calibration's pose rule, a tracker reading at each, a measurement file. */
    private void campaign(CommandInvoker inv, ProtocolClient client, PrintWriter o) throws Exception {
        expectArgs(0, "campaign --poses N --out FILE");
        if (out == null) throw new IllegalArgumentException("campaign needs --out FILE (the measurement file)");
        if (poses < 1) throw new IllegalArgumentException("--poses must be >= 1, got " + poses);
        if (Files.exists(out) && !force) throw new IllegalArgumentException("refusing to overwrite " + out + " (give --force)");
        inv.execute(Commands.ping());
        String robotName = robot != null ? robot : client.robotName();
        if (robotName == null || robotName.isBlank())
            throw new IllegalArgumentException("the controller does not say which robot it is; give --robot ROBOT");
        RobotDescription d = RobotLibrary.load(robotName);
        KinematicModel model = KinematicModel.build(d);
        List<double[]> qs = MeasurementCampaign.samplePoses(model, poses, seed);
        PrintWriter e = spec.commandLine().getErr();
        List<JointType> types = d.joints().stream().map(j -> j.type()).toList();
        // Every pose is appended to FILE.journal (synced) as it is measured; the journal becomes FILE at the end.
        Path journalFile = out.resolveSibling(out.getFileName() + ".journal");
        Map<String, String> meta = MeasurementCampaign.metadata(d.name(), "laser tracker via " + client.channel().describe());
        meta.put("campaign", "poses " + poses + ", seed " + seed);
        MeasurementSet done = null;
        MeasurementJournal journal;
        if (Files.exists(journalFile)) {
            if (!resume)
                throw new IllegalArgumentException(journalFile + " holds an interrupted campaign; give --resume to continue it"
                        + " (same --poses, --seed, --robot), or delete it to start again");
            done = MeasurementJournal.recover(journalFile, types);
            if (done != null && !(meta.get("campaign").equals(done.metadata().get("campaign"))
                    && meta.get("robot").equals(done.metadata().get("robot"))))
                throw new IllegalArgumentException(journalFile + " is a campaign of " + done.metadata().get("robot") + " with "
                        + done.metadata().get("campaign") + "; resume it with the same --poses, --seed and --robot");
            journal = MeasurementJournal.resume(journalFile, done, types);
            if (done == null) journal = journal.withHeader(meta, "tracker", model.dof());
            else meta = done.metadata();
            e.println("resuming: " + (done == null ? 0 : done.size()) + " of " + qs.size() + " poses already measured");
        } else {
            journal = MeasurementJournal.create(journalFile, meta, "tracker", model.dof(), types);
        }
        MeasurementSet set;
        try (MeasurementJournal j = journal) {
            try {
                set = MeasurementCampaign.run(inv, qs, meta, j, done, k -> {
                    if (k % 25 == 0 || k == qs.size()) {
                        e.println("measured " + k + " / " + qs.size() + " poses");
                        e.flush();
                    }
                });
            } catch (MeasurementCampaign.Stopped stopped) {
                // Keep the exit code of the cause (4 refused, 3 link), say at which pose it stopped and where the rest is.
                String msg = stopped.getMessage() + "; the " + j.rows() + " poses measured are kept in " + journalFile
                        + " (run the same command with --resume to continue)";
                if (stopped.getCause() instanceof CommsException.Refused r) throw new CommsException.Refused(r.code(), msg);
                throw new CommsException.Protocol(msg);
            }
            j.finish(out, force);
        }
        Measurement last = set.rows().get(set.size() - 1);
        o.println(String.format(Locale.ROOT, "wrote %s: %d poses, %.1f s of controller time%s", out, set.size(), last.timeS(),
                Double.isNaN(last.tempC()) ? "" : String.format(Locale.ROOT, ", temperature %.1f °C at the end", last.tempC())));
    }

    private static String pose(Pose p) {
        double[] q = p.quaternion();
        return OpenAbb.num(Units.mToMm(p.x()), 3) + " " + OpenAbb.num(Units.mToMm(p.y()), 3) + " " + OpenAbb.num(Units.mToMm(p.z()), 3)
                + "  " + OpenAbb.num(q[0], 6) + " " + OpenAbb.num(q[1], 6) + " " + OpenAbb.num(q[2], 6) + " " + OpenAbb.num(q[3], 6)
                + "  (mm; quaternion q1..q4)";
    }

    private static String status(ControllerStatus st) {
        return st.state() + (st.program().isEmpty() ? "" : " " + st.program()) + String.format(Locale.ROOT, ", clock %.3f s", st.clockS())
                + ", " + st.errorCount() + " error(s)"
                + (st.lastError() == null ? "" : ", last " + st.lastError().wire() + " " + st.lastErrorMessage());
    }
}
