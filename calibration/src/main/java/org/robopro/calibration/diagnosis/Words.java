package org.robopro.calibration.diagnosis;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.EigenDecomposition_F64;

/** Findings in plain words for the report. */
final class Words {
    private Words() { }

    /**
     * @param sizeM for a lost motion, the displacement of the measured point by its full half-play (RMS over the
     *              poses, m); NaN when not known
     */
    /**
     * Whether a base tilt's pivot lies below the base plate, from its slide ({@link Effect#baseTilt}:
     * c = a·d with d the pivot's depth) when both the tilt and the slide are told from zero (beyond
     * twice their standard deviations). The depth itself is not given: on campaigns of a pedestal
     * rocking on its foot 0.4-0.8 m down, c/a came out anywhere from 0.2 to 1.8 m with standard
     * deviations that did not cover the truth, while its sign held.
     */
    static String pivotWords(double[] v, double[] s) {
        if (!(v[2] > 2 * s[2]) || !(v[0] > 2 * s[0])) return "";
        return " The base also slides toward the lean as it tilts, so it rocks about a point below its base plate: the robot "
                + "stands on a pedestal, a riser or a slab that gives way, not on its own foot alone.";
    }

    static String finding(Effect e, double[] v, double[] s, Diagnosis.Evidence ev, double trainBefore, double trainAfter,
                          double valBefore, double valAfter, Directions.Source dirs, double sizeM) {
        return finding(e, v, s, ev, trainBefore, trainAfter, valBefore, valAfter, dirs, sizeM, null);
    }

    /**
     * A finding's words; {@code spring}, for a link's bending, the words of the spring of the link's own
     * joint that predicts left-out poses as well ({@link #springAlike}), or null.
     */
    static String finding(Effect e, double[] v, double[] s, Diagnosis.Evidence ev, double trainBefore, double trainAfter,
                          double valBefore, double valAfter, Directions.Source dirs, double sizeM, String spring) {
        String at = Double.isFinite(sizeM) ? String.format(Locale.ROOT, ", %.4f mm at the measured point (RMS over the poses)", sizeM * 1e3) : "";
        String what = switch (e.kind()) {
            case COMPLIANCE -> e.gravity().massesUnknown()
                    ? String.format(Locale.ROOT, "Joint %d gives way under gravity: the payload steps give its compliance %.3g ± %.2g "
                    + "rad/(N·m), a stiffness of %.3g N·m/rad. The robot file has no mass model, so the arm's own weight was "
                    + "estimated with it (unknown masses and centres of links 1-3, coefficients %s).", e.joint() + 1,
                    v[e.gravity().payloadIndex()], s[e.gravity().payloadIndex()], 1 / v[e.gravity().payloadIndex()], fmtList(v))
                    : e.perMass()
                    ? String.format(Locale.ROOT, "Joint %d gives way under gravity, and the robot file's masses do not match: with "
                    + "each mass's torque on drive %d given its own coefficient (the mass model re-estimated from the data) the "
                    + "deflection is explained; coefficients %s rad/(N·m) per N·m of the file's torque (%s).", e.joint() + 1,
                    e.joint() + 1, fmtList(v), String.join(", ", e.parameterNames()))
                    : e.stiffens()
                    ? String.format(Locale.ROOT, "Joint %d gives way under the arm's weight, with a spring that stiffens as it is "
                    + "loaded (as strain-wave and cycloidal reducers do): compliance %.3g ± %.2g rad/(N·m) unloaded, a stiffness of "
                    + "%.3g N·m/rad, and a cubic term %.3g ± %.2g rad/(N·m)³%s.", e.joint() + 1, v[0], s[0], 1 / v[0], v[1], s[1],
                    Double.isFinite(Effect.stiffnessDoublesAtNm(v)) ? String.format(Locale.ROOT,
                    "; the stiffness doubles by about %.0f N·m", Effect.stiffnessDoublesAtNm(v)) : "")
                    : String.format(Locale.ROOT, "Joint %d gives way under the arm's weight: compliance %.3g ± %.2g "
                    + "rad/(N·m), a stiffness of %.3g N·m/rad.", e.joint() + 1, v[0], s[0], 1 / v[0]);
            case PERIODIC -> {
                double[] hs = e.orders();
                if (e.shaftOrders()) {
                    StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "Joint %d's error repeats at the turn of a shaft "
                            + "that turns many times per turn of the joint, not at the joint's own turn:", e.joint() + 1));
                    for (int i = 0; i < hs.length; i++)
                        sb.append(String.format(Locale.ROOT, " %s cycles per turn %.4f ± %.4f deg%s", Effect.orderText(hs[i]),
                                Math.toDegrees(Math.hypot(v[2 * i], v[2 * i + 1])), Math.toDegrees(Math.max(s[2 * i], s[2 * i + 1])),
                                i < hs.length - 1 ? "," : "."));
                    sb.append(String.format(Locale.ROOT, " At the joint's gear ratio that shaft is the motor: the error of its angle "
                            + "sensor (a resolver's or an encoder's, once and twice per motor turn) and of the reducer's input stage "
                            + "repeat alike there, and measurements of the arm cannot tell them apart; an intermediate shaft of the "
                            + "drive gives such an order too. Compare the order with joint %d's gear ratio (the drive's data sheet), and "
                            + "the motor's encoder with an encoder on the output side, to tell which. It is modelled as sinusoids at "
                            + "those orders so compensation can use it.", e.joint() + 1));
                    yield sb.toString();
                }
                StringBuilder sb = new StringBuilder(String.format(Locale.ROOT,
                        "Joint %d has a transmission error that repeats with its angle (%s):", e.joint() + 1,
                        hs[hs.length - 1] > 3 ? "cycles of a multi-stage or cycloidal reducer" : "gear or encoder eccentricity"));
                for (int i = 0; i < hs.length; i++)
                    sb.append(String.format(Locale.ROOT, " %s cycle%s per turn%s %.4f ± %.4f deg%s", Effect.orderText(hs[i]), hs[i] == 1 ? "" : "s",
                            hs[i] > Effect.HARMONICS ? " (a stage turning " + Effect.orderText(hs[i]) + " times per output turn: a reducer's "
                                    + "stage, or, at the joint's gear ratio, the motor itself, whose resolver or encoder error "
                                    + "repeats there the same way)" : "",
                            Math.toDegrees(Math.hypot(v[2 * i], v[2 * i + 1])),
                            Math.toDegrees(Math.max(s[2 * i], s[2 * i + 1])), i < hs.length - 1 ? "," : "."));
                if (ev.projectionRatio() < 0.3)
                    sb.append(String.format(Locale.ROOT, " Only %.0f %% of its signature is distinct from geometry on these poses, "
                            + "so the amplitudes are uncertain; a wider range of joint %d would separate them.",
                            100 * ev.projectionRatio(), e.joint() + 1));
                if (!ev.absorbed().isEmpty())
                    sb.append(" Terms ").append(String.join(", ", ev.absorbed()))
                            .append(" look like geometry on these poses and were left to the geometric model.");
                yield sb.toString();
            }
            case SMOOTH -> e.angleJoint() == e.joint() && e.followsModelAngle() ? String.format(Locale.ROOT, "Joint %d's error follows "
                    + "its own angle in the arm, θ%d (on a parallel arm the forearm's angle to the upper arm), not its drive's value q%d: "
                    + "%.4f deg RMS over %.0f..%.0f deg of θ%d. None of the known effects explains it (a parallel arm's rod or lever of "
                    + "the wrong length turns the forearm by such a function of θ%d, the four-bar linkage's closure). It is modelled as a "
                    + "smooth curve of θ%d (%d-function cubic spline) so compensation can use it, but its cause is unknown.",
                    e.joint() + 1, e.joint() + 1, e.joint() + 1, Math.toDegrees(rmsSmooth(e, v)), Math.toDegrees(e.rangeLo()),
                    Math.toDegrees(e.rangeHi()), e.joint() + 1, e.joint() + 1, e.joint() + 1, e.basisCount())
                    : e.angleJoint() != e.joint() ? String.format(Locale.ROOT, "Joint %d's error follows joint %d's angle, not in "
                    + "proportion to it (%.4f deg RMS over joint %d's range, %.0f..%.0f deg), so it is no cross-coupling; none of the known "
                    + "effects explains it (a cable or hose pulling as joint %d winds up, a linkage's play?). It is modelled as a smooth "
                    + "curve of joint %d's angle (%d-function cubic spline) so compensation can use it, but its cause is unknown.",
                    e.joint() + 1, e.angleJoint() + 1, Math.toDegrees(rmsSmooth(e, v)), e.angleJoint() + 1, Math.toDegrees(e.rangeLo()),
                    Math.toDegrees(e.rangeHi()), e.angleJoint() + 1, e.angleJoint() + 1, e.basisCount())
                    : String.format(Locale.ROOT, "Joint %d has an angle-dependent error of %.4f deg (RMS over its range) that "
                    + "none of the known effects explains; it is modelled as a smooth curve of the joint angle (%d-function "
                    + "cubic spline over %.0f..%.0f deg) so compensation can use it, but its cause is unknown.", e.joint() + 1,
                    Math.toDegrees(rmsSmooth(e, v)), e.basisCount(), Math.toDegrees(e.rangeLo()), Math.toDegrees(e.rangeHi()))
                    + shortRange(e);
            case GRAVITY_PLAY -> v[0] >= 0 ? String.format(Locale.ROOT, "Joint %d has a play of %.4f ± %.4f deg taken up by gravity: "
                    + "its output rests on the side the gravity torque on it pushes it to, changing side where that torque crosses "
                    + "%.1f N·m%s, whatever way the joint last moved, so no motion's direction shows it. A clearance in the joint's "
                    + "bearing, gear or linkage held by the arm's weight does so; none of the known effects explains it (a backlash "
                    + "would follow the last motion where the torque is small). It is modelled as such so compensation can use it. To "
                    + "tell a gear's backlash from a bearing's clearance, measure poses where the torque on joint %d is small, "
                    + "approached from both directions.", e.joint() + 1, Math.toDegrees(v[0]), Math.toDegrees(s[0]), e.sideNm(),
                    e.sideWidthNm() > 0 ? String.format(Locale.ROOT, " (over ± %.1f N·m)", e.sideWidthNm()) : "", e.joint() + 1)
                    : String.format(Locale.ROOT, "Joint %d's reading steps by %.4f ± %.4f deg where the gravity torque on it changes "
                    + "sign (at %.1f N·m%s, by the robot file's masses), whatever way the joint last moved, but against the torque: "
                    + "a clearance held by the arm's weight gives way with the torque, as a spring does, so this is no play taken up "
                    + "by gravity as the file's masses put it, and none of the known effects explains it. Check the mass model's "
                    + "centres of mass for joint %d (a mass on the wrong side of the axis turns the torque's sign). It is modelled as "
                    + "such so compensation can use it.", e.joint() + 1, Math.toDegrees(-v[0]), Math.toDegrees(s[0]), e.sideNm(),
                    e.sideWidthNm() > 0 ? String.format(Locale.ROOT, " ± %.1f", e.sideWidthNm()) : "", e.joint() + 1);
            case LOAD_PERIODIC -> {
                double[] hs = e.orders();
                double[] amp = sizeAndChange(v, hs.length);
                double at0 = amp[0], per = amp[1];
                yield String.format(Locale.ROOT, "Joint %d's error repeats %s times per turn of its angle, and its size follows the "
                        + "gravity torque on the joint (%s): %.4f deg without load, changing by %.4f deg per %.0f N·m (amplitudes "
                        + "over the orders, root-sum-square). A gear mesh that deflects more under load does so (the loaded "
                        + "transmission error); a transmission error of fixed size does not explain it, so no known family is named. "
                        + "It is modelled as such so compensation can use it. To confirm, measure the same angles of joint %d with "
                        + "two or three payloads.", e.joint() + 1, String.join(", ", java.util.Arrays.stream(hs).mapToObj(Effect::orderText).toList()),
                        e.loadMagnitude() ? "its size, whichever way it turns the joint" : "with its sign", Math.toDegrees(Math.sqrt(at0)),
                        Math.toDegrees(Math.sqrt(per)), e.loadRefNm(), e.joint() + 1);
            }
            case WARM_PERIODIC -> {
                int[] hs = e.harmonics();
                double[] amp = sizeAndChange(v, hs.length);
                double at0 = amp[0], per = amp[1];
                yield String.format(Locale.ROOT, "Joint %d's error repeats %s times per turn of its angle, and its size changes with "
                        + "the temperature: %.4f deg at %.1f °C, changing by %.4f deg up to %.1f °C (amplitudes over the orders, "
                        + "root-sum-square). An encoder whose sine and cosine channels drift apart as it warms does so (a gain "
                        + "mismatch reads twice per turn wrong, an offset once); a transmission error keeps its size, so no known family "
                        + "is named. It is modelled as such so compensation can use it at the temperature read. To confirm, measure the "
                        + "same angles of joint %d cold and warmed through, with the temperature at the joint recorded.", e.joint() + 1,
                        String.join(", ", java.util.Arrays.stream(hs).mapToObj(String::valueOf).toList()), Math.toDegrees(Math.sqrt(at0)),
                        e.rangeLo(), Math.toDegrees(Math.sqrt(per)), e.rangeHi(), e.joint() + 1);
            }
            case LINK_PERIODIC -> {
                int[] hs = e.harmonics();
                double rss = 0;
                for (double x : v) rss += x * x;
                if (e.followsAnotherJoint())
                    yield String.format(Locale.ROOT, "Joint %d's error repeats %s times per turn of joint %s's angle (%.4f deg, amplitudes "
                            + "root-sum-square), not with joint %d's own angle: joint %d's drive passes through the housing that joint %s "
                            + "turns, and a bearing seat or a gear there out of round (an oval seat repeats twice a turn) changes its "
                            + "transmission as the housing turns. No transmission error of the drive repeats so, so no known family is "
                            + "named. It is modelled as such so compensation can use it. To confirm, hold joint %d and turn joint %s "
                            + "through a whole turn in small steps.", e.joint() + 1,
                            String.join(", ", java.util.Arrays.stream(hs).mapToObj(String::valueOf).toList()), e.linkAngleText().substring(1),
                            Math.toDegrees(Math.sqrt(rss)), e.joint() + 1, e.joint() + 1, e.linkAngleText().substring(1), e.joint() + 1,
                            e.linkAngleText().substring(1));
                yield String.format(Locale.ROOT, "Joint %d's error repeats %s times per turn of the link angle %s (%.4f deg, amplitudes "
                        + "root-sum-square), not with joint %d's own angle: the angle of its link against the link before it, or against "
                        + "the ground, which a linkage's rod, lever or bearing, or a counterweight's, turns with. No transmission error of "
                        + "the drive repeats so, so no known family is named. It is modelled as such so compensation can use it. To confirm, "
                        + "measure poses that hold %s fixed while joint %d turns, and the other way round.", e.joint() + 1,
                        String.join(", ", java.util.Arrays.stream(hs).mapToObj(String::valueOf).toList()), e.linkAngleText(),
                        Math.toDegrees(Math.sqrt(rss)), e.joint() + 1, e.linkAngleText(), e.joint() + 1);
            }
            case COMPLIANCE_VARYING -> {
                // a clamped B-spline starts at its first coefficient and ends at its last; per mass, the payload's pair
                int pay = e.gravity().payloadIndex();
                boolean perMass = e.gravity().massesUnknown() && !e.payloadShare();
                int per = e.payloadCentreFree() ? 4 : 1;   // with the payload's centre estimated, each function's first column is the file's centre
                double c0 = perMass ? v[2 * pay] : v[0], c1 = perMass ? v[2 * pay + 1] : v[v.length - per];
                boolean time = e.along() == Effect.Along.TIME;
                String centre = e.payloadCentreFree() ? payloadCentreText(v) : "";
                if (e.stepTimes() != null)
                    yield centre + String.format(Locale.ROOT, "Joint %d gives way under the payload's weight by an amount that steps at %s: "
                            + "a compliance of %.3g rad per kN·m before the first step and %.3g after the last (a stiffness of %s and %s "
                            + "kN·m/rad), not the one stiffness of a joint compliance, so no known family is named. A carried mass that "
                            + "changes at moments while payload_kg stays as recorded does so (a dispensing tool's shots, a part dropped or "
                            + "added): the torque follows the mass, the compliance stays. It is modelled as such for these poses. Record the "
                            + "carried mass as it changes (payload_kg per pose).", e.joint() + 1,
                            String.join(", ", java.util.Arrays.stream(e.stepTimes()).mapToObj(t -> String.format(Locale.ROOT, "%.0f s", t)).toList()),
                            c0 * 1e3, c1 * 1e3, stiffnessText(c0), stiffnessText(c1));
                yield centre + String.format(Locale.ROOT, "Joint %d gives way under %s, and by an amount that changes with %s: a compliance "
                        + "of %.3g rad per kN·m at %.4g %s and %.3g at %.4g %s (a stiffness of %s and %s kN·m/rad), not the one "
                        + "stiffness of a joint compliance, so no known family is named. %s It is modelled as such for these poses. %s",
                        e.joint() + 1, e.payloadShare() ? "the payload's weight" : "the arm's weight", e.along().words, c0 * 1e3, e.rangeLo(),
                        e.along().unit, c1 * 1e3, e.rangeHi(), e.along().unit, stiffnessText(c0), stiffnessText(c1),
                        e.payloadShare() ? "A carried mass that changes while payload_kg stays as recorded does so (a dispensing or gluing "
                                + "tool emptying, a part dropped): the torque follows the mass, the compliance stays."
                                : time ? "A stiffness that falls as the joint warms with work does so, or a carried mass that changes."
                                : "A stiffness that falls as the joint warms does so (a reducer's lubricant thins, its seals soften).",
                        e.payloadShare() || time ? "Record the carried mass as it changes (payload_kg per pose), or weigh the tool before "
                                + "and after, and measure a few poses again at the campaign's end."
                                : "Measure the same poses cold and warmed through, with the joint's temperature recorded, to see the "
                                + "stiffness change; compensate at the temperature the robot works at.");
            }
            case PAIR -> String.format(Locale.ROOT, "Joint %d's error depends on joints %d and %d together (%.4f deg RMS over the "
                    + "poses, in products of their sines and cosines, beside terms linear in each angle and in their product) and none of the known effects explains it; it is modelled "
                    + "as such so compensation can use it, but its cause is unknown.", e.joint() + 1, e.joint() + 1, e.source() + 1,
                    Math.toDegrees(Math.sqrt((v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]) / 4)));
            case BASE_TURN -> baseTurn(e, v);
            case INSTRUMENT_SCALE -> instrumentScale(e, v, at);
            case INSTRUMENT_AXES -> String.format(Locale.ROOT, "The measured positions are off by a constant linear map of the "
                    + "instrument's own coordinates that no placement of it explains: its x and y axes scaled by %+.1f and %+.1f ppm "
                    + "against its z axis, and out of square by %+.1f µrad (x, y), %+.1f µrad (x, z) and %+.1f µrad (y, z)%s%s. No error of "
                    + "the robot moves points so: the instrument's axes are not square and of one scale (a coordinate measuring "
                    + "machine's squareness, a camera system's depth scale against its lateral scale), or another error of the "
                    + "measurement grows across the measured volume (the air bending the beam). It is modelled so that it "
                    + "does not bend the robot's fit, and left out of compensation: measure a calibrated artefact (a ball bar or a "
                    + "scale bar in several directions across the volume) with the instrument.", 1e6 * v[0], 1e6 * v[1],
                    2e6 * v[2], 2e6 * v[3], 2e6 * v[4], e.bowed() ? String.format(Locale.ROOT, "; its ways bowed: the x travel moves the "
                    + "point by %+.1f and %+.1f µm/m² along y and z, the y travel by %+.1f and %+.1f along x and z, the z travel by %+.1f "
                    + "and %+.1f along x and y (a straightness error of its ways)", 1e6 * v[5], 1e6 * v[6], 1e6 * v[7], 1e6 * v[8], 1e6 * v[9],
                    1e6 * v[10]) : "", at);
            case REFRACTION -> refraction(e, v);
            case POINT_SMOOTH -> String.format(Locale.ROOT, "The measured point moves with %s (a smooth displacement in the "
                    + "base frame over %.4g..%.4g %s) and none of the known effects explains it; it is modelled as such so "
                    + "compensation can use it, but its cause is unknown (%s).", e.along() == Effect.Along.REACH
                    || e.along() == Effect.Along.HEIGHT ? "its " + e.along().words : e.along().words, e.rangeLo(), e.rangeHi(), e.along().unit,
                    e.along() == Effect.Along.REACH || e.along() == Effect.Along.HEIGHT || e.along() == Effect.Along.PAYLOAD_REACH
                            ? "sag of the arm or the point's holder, the instrument's scale or levelling"
                            : "the instrument or the target moved, or the base; re-measure a fixed reference point every few poses");
            case BASE_TILT -> e.towardLean() ? String.format(Locale.ROOT, "The robot's base tilts on its foundation toward whichever "
                    + "side the arm leans, about the axis of the moment of its weight and payload (%.3g µrad per 100 N·m%s), and none of "
                    + "the known effects of the arm explains it: anchor bolts slack all round, a foot that rocks on its pad, a soft floor "
                    + "or pedestal. It is modelled as such so compensation can use it, but check the base's bolts and its seating: "
                    + "measure a point on the base itself while the arm reaches out in several directions with and without payload.",
                    1e8 * v[0], e.tiltHold() > 0 ? String.format(Locale.ROOT, ", once the moment exceeds %.0f N·m", e.tiltHold()) : "")
                    : e.squareFoot() ? String.format(Locale.ROOT, "The robot's base rocks on a square foot over whichever of its "
                    + "edges the arm's weight and payload push it past (edges' axes at %.0f deg and every 90 deg from it, %.3g µrad per "
                    + "100 N·m once the moment about an edge exceeds %.0f N·m), and none of the known effects of the arm explains it: "
                    + "anchor bolts slack at the corners, a base plate that rocks on its grout. It is modelled as such so compensation "
                    + "can use it, but check the base's bolts and its seating: measure a point on the base itself while the arm reaches "
                    + "out in several directions with and without payload.", (Math.toDegrees(e.tiltAzimuth()) % 90 + 90) % 90, 1e8 * v[0], e.tiltHold())
                    : String.format(Locale.ROOT, "The robot's base tilts on its foundation about a horizontal axis at %.0f deg "
                    + "as the arm's weight and payload tip it (%.3g µrad per 100 N·m%s), and none of the known effects of the arm "
                    + "explains it: a loose anchor bolt, a foot that rocks over its edge, a soft floor or pedestal. It is modelled as such "
                    + "so compensation can use it, but check the base's bolts and its seating: measure a point on the base itself "
                    + "while the arm reaches out in several directions with and without payload.", Math.toDegrees(e.tiltAzimuth()),
                    1e8 * v[0], Double.isInfinite(e.tiltHold()) ? ", in both directions" : String.format(Locale.ROOT,
                            ", once the moment about that edge exceeds %.0f N·m", e.tiltHold()));
            case LINK_SAG -> {
                String bend = String.format(Locale.ROOT, "its far end moves %.4f mm across it and turns %.4f deg when it lies "
                        + "horizontal (its own weight and what it carries%s)", 1e3 * Math.abs(v[0]), Math.toDegrees(Math.abs(v[1])),
                        e.sagPayload() ? ", beside the payload's" : "");
                String link = e.joint() == 1 ? "upper arm (joint 2 to joint 3)" : "forearm (joint 3 to the wrist)";
                yield spring == null ? String.format(Locale.ROOT, "The %s bends under gravity as a beam: %s, and none of the known "
                        + "effects explains it (a joint's spring turns the whole link about its axis, a beam bends along it). It is "
                        + "modelled as such so compensation can use it, but check the link: measure a target at the %s's far end "
                        + "(on joint %d's housing) with the link horizontal and vertical, with and without payload.", link, bend,
                        linkName(e), e.joint() + 2)
                        : String.format(Locale.ROOT, "The %s bends under gravity as a beam, or joint %d gives way under it: modelled "
                        + "as a bending, %s. %s", link, e.joint() + 1, bend, spring);
            }
            case LINK_TWIST -> String.format(Locale.ROOT, "The upper arm (joint 2 to joint 3) twists about its long axis under the "
                    + "torque of the weights beyond it%s, which the wrist swings across the arm's plane (the tool's and the payload's), "
                    + "and none of the known effects explains it (a joint's spring turns about the joint's axis, a twist about the "
                    + "link's). It is modelled as such so compensation can use it, but check the upper arm and the tool's weight and "
                    + "centre: measure two targets on joint 3's housing either side of the arm's plane with the tool's weight hung "
                    + "to one side and then the other.", at);
            case TOOL_PLAY -> String.format(Locale.ROOT, "The measured point moves across the tool's axis toward the side gravity "
                    + "pulls the tool to, by about %.4f mm whichever way that is once the tool leans, and none of the known effects "
                    + "explains it: a play taken up by the tool's weight (a loose target nest or tool mount, or clearance in the "
                    + "flange's bearing), not a holder that bends (that moves in proportion to the pull). It is modelled as such so "
                    + "compensation can use it, but check the mount: measure one place with the tool leaning one way and then the "
                    + "other; tighten the nest or the mount, or check the flange bearing's preload.", 1e3 * rmsOverCircle(v));
            case SECOND_STATION -> String.format(Locale.ROOT, "The poses whose target faces (%.2f, %.2f, %.2f) in the base frame are moved "
                    + "against the rest by one rigid motion, %.4f mm and %.1f µrad, whatever the arm's pose, and none of the known effects "
                    + "explains it: they were read from a second instrument station (a second tracker, or the one moved, seeing the "
                    + "reflector the first could not) whose registration into the first's frame is off, not the robot. It is modelled so "
                    + "that it does not bend the robot's fit, and left out of compensation: register the stations again on common "
                    + "targets, or record which station read each pose.", e.facing().x(), e.facing().y(), e.facing().z(),
                    1e3 * Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1e6 * Math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]));
            case LOAD_TILT -> String.format(Locale.ROOT, "The axis of joint %d tilts across itself with the torque its drive "
                    + "carries, %.4f deg at the largest on these poses (%.1f N·m), and none of the known effects explains it: the "
                    + "gear mesh's tooth and separating forces bend the drive's output shaft on its bearings (a joint's spring under "
                    + "the same torque turns it about its axis; this tilts the axis). It is modelled as such so compensation can use "
                    + "it, but check the drive's output bearings and the shaft: put an electronic level or a dial indicator on the "
                    + "link beyond joint %d and read its tilt across the axis with the arm held out and then folded in.",
                    e.joint() + 1, Math.toDegrees(Math.hypot(Math.abs(v[0]) + Math.abs(v[1]), Math.abs(v[2]) + Math.abs(v[3]))), e.loadRefNm(),
                    e.joint() + 1);
            case TOOL_PULL -> String.format(Locale.ROOT, "The measured point moves as if the tool were pulled by a steady force from "
                    + "outside the robot, %s, each joint yielding to it through its stiffness%s, and none of the known effects "
                    + "explains it (a joint's spring yields to the weights, which pull straight down, "
                    + "and to a payload as the file records it): a hose or cable retractor, a balancer or a dress pack hung from a boom pulling the tool. It is "
                    + "modelled as such so compensation can use it, but check what hangs on the tool: measure a few poses with it "
                    + "unhooked and again hooked.", pullWhere(e, v), at);
            case TOOL_SAG -> String.format(Locale.ROOT, "The measured point moves with the direction of gravity seen from the "
                    + "flange (it drops %.4f mm more with its holder turned to its softest direction than to its stiffest: a bar held "
                    + "across gravity against along it), and none of the "
                    + "known effects explains it: the point's holder (an extension bar, the target's nest, the tool) bends under its "
                    + "own weight. It is modelled as such so compensation can use it, but check the holder: measure the point with the "
                    + "flange pointing down, then sideways, at one place, or shorten and stiffen the holder.", 1e3 * sagSpan(v));
            case AXIS_WOBBLE -> String.format(Locale.ROOT, "The axis of joint %d tilts across itself as the joint turns (%s), "
                    + "%.4f deg (%.1f arc-seconds) RMS over a turn, and none of the known effects explains it: the joint's bearing "
                    + "wobbles (runout or waviness of a race, a worn or unloaded main bearing). It is modelled as such so compensation "
                    + "can use it, but check the bearing: put a dial indicator or an electronic level on the link beyond joint %d and "
                    + "read its tilt across the axis while the joint turns slowly through its range.", e.joint() + 1,
                    wobbleOrders(e), Math.toDegrees(rmsOverCircle(v)), Math.toDegrees(rmsOverCircle(v)) * 3600, e.joint() + 1)
                    + (e.joint() >= 3 ? String.format(Locale.ROOT, " On the wrist, whose axes meet, a tilt across joint %d's axis is also "
                    + "what a neighbouring wrist drive does when its error follows joint %d's angle (a cable or dress pack pulling on the "
                    + "wrist as it winds, a coupling of the wrist's drives), and these poses cannot tell the two apart.", e.joint() + 1,
                    e.joint() + 1) : "");
            case AXIAL_RUNOUT -> String.format(Locale.ROOT, "Everything beyond joint %d moves along the joint's axis as it turns (%s), "
                    + "%.4f mm RMS over a turn, and none of the known effects explains it: the joint's bearing runs out axially "
                    + "(waviness or a face runout of a race, a worn or unloaded main bearing), which no error of a joint's angle and "
                    + "no tilt of its axis does. It is modelled as such so compensation can use it, but check the bearing: put a dial "
                    + "indicator on the link beyond joint %d, along the axis, and read it while the joint turns slowly through its "
                    + "range, both ways.", e.joint() + 1, wobbleOrders(e), 1e3 * rmsOverCircle(v), e.joint() + 1);
            case TARGET_INCIDENCE -> "The measured positions err with the direction the instrument sees the point from, in the "
                    + "tool's frame" + at + ", and none of the known effects explains it: the reflector, not the robot (a glass-prism "
                    + "reflector seen off its axis refracts the beam, a reflector's optical centre off its sphere's). It is modelled so "
                    + "that it does not bend the robot's fit, and left out of compensation: measure with an open-air (hollow) reflector, "
                    + "or turn the reflector in its nest toward the instrument at each pose, and measure again.";
            case INSTRUMENT -> e.sight() == Effect.Sight.RANGE ? String.format(Locale.ROOT, "The measured positions err along the "
                    + "instrument's line of sight as a function of its distance reading (%.4f mm RMS over %.3f..%.3f m%s), which no error "
                    + "of the robot explains: the instrument's distance meter (a cyclic error or a scale error of its interferometer or "
                    + "absolute distance meter), not the robot. It is modelled so that it does not bend the robot's fit, and left out of "
                    + "compensation: check the distance meter against a known length at several distances (the instrument's own "
                    + "compensation or a field check) and measure again.", 1e3 * rmsInstrument(e, v), e.rangeLo(), e.rangeHi(),
                    Double.isFinite(e.cycle()) ? String.format(Locale.ROOT, ", repeating every %.0f mm%s", 1e3 * e.cycle(),
                            e.cycleOrders() > 1 ? " and at its harmonics up to " + e.cycleOrders() : "") : "")
                    : String.format(Locale.ROOT, "The measured positions err across the instrument's line of sight as a function of its "
                    + "%s reading (%.2f arc-seconds RMS over %.0f..%.0f deg), which no error of the robot explains: the instrument's %s "
                    + "(an angle encoder's error or its axes' misalignment), not the robot. It is modelled so that it does not bend the "
                    + "robot's fit, and left out of compensation: run the instrument's two-face (front and back sight) check and its "
                    + "compensation, and measure again.", e.sight().words, Math.toDegrees(rmsInstrument(e, v)) * 3600,
                    Math.toDegrees(e.rangeLo()), Math.toDegrees(e.rangeHi()), e.sight() == Effect.Sight.AZIMUTH
                    ? "horizontal angle" : "vertical angle");
            case ANGLE_STEP -> e.isWindow() ? String.format(Locale.ROOT, "Joint %d's reading is off by %.4f deg while the joint is "
                    + "between %.1f and %.1f deg, and none of the known effects explains it (an encoder's code track or scale misread "
                    + "over one window of the turn); it is modelled as such so compensation can use it, but its cause is unknown: "
                    + "move the joint slowly across that window in both directions and compare with an independent measure.",
                    e.joint() + 1, Math.toDegrees(v[0]), Math.toDegrees(e.rangeLo()), Math.toDegrees(e.rangeHi()))
                    : String.format(Locale.ROOT, "Joint %d's reading jumps by %.4f deg where the joint passes %.1f deg, "
                    + "and none of the known effects explains it (an absolute encoder's code track or a bit misread over part of "
                    + "the turn, a damaged scale); it is modelled as such so compensation can use it, but its cause is unknown: "
                    + "move the joint slowly across that angle in both directions and compare with an independent measure.",
                    e.joint() + 1, Math.toDegrees(v[0]), Math.toDegrees(e.rangeLo()));
            case BASE_CREEP -> String.format(Locale.ROOT, "The robot's base turns on its floor a little with each move of joint 1 over "
                    + "%.0f deg, in the move's direction: %.1f ± %.1f µrad per move (and %.4f, %.4f mm across, a pivot off joint 1's axis), "
                    + "adding up over the campaign, and none of the known effects explains it. Anchor bolts that slip under the reaction "
                    + "of the arm's acceleration do so. It is modelled as such for these poses; a program run later meets the base "
                    + "where the campaign left it, and every large move turns it further. Check the base's bolts and their torque, and "
                    + "measure a fixed reference point on the base or the floor between moves.", Math.toDegrees(e.creepMoveRad()),
                    v[0] * 1e6, s[0] * 1e6, v[1] * 1e3, v[2] * 1e3);
            case TARGET_DRIFT -> {
                // the drift's range along each flange axis over the campaign (a B-spline's curve lies within its coefficients)
                int n = e.basisCount();
                double[] span = new double[3];
                for (int a = 0; a < 3; a++) {
                    double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
                    for (int i = 0; i < n; i++) { lo = Math.min(lo, v[a * n + i]); hi = Math.max(hi, v[a * n + i]); }
                    span[a] = hi - lo;
                }
                yield String.format(Locale.ROOT, "The measured point moves on the flange with time, by up to %.4f, %.4f and %.4f mm along "
                        + "the flange's x, y and z axes over %.0f..%.0f s, and none of the known effects explains it: a tool that grows "
                        + "and shrinks as a spindle or the tool warms and cools (along its axis, the flange's z), a holder that creeps. "
                        + "It is modelled as a smooth curve of time in the flange's axes (%d functions each) so the poses are compared "
                        + "with the point where it was; re-measure one pose every few minutes through a campaign to see it, and warm "
                        + "the tool up before measuring.", span[0] * 1e3, span[1] * 1e3, span[2] * 1e3, e.rangeLo(), e.rangeHi(), n);
            }
            case TARGET_STEP -> String.format(Locale.ROOT, "The measured point moved on the flange by %.4f mm (%.4f, %.4f, %.4f mm "
                    + "along the flange's axes) at about %.0f s into the campaign, and none of the known effects explains it (a "
                    + "target knocked in its nest, a holder that slipped); the poses before it are modelled with the point where it "
                    + "was then, but check the target's mounting and re-measure a few poses from before that time.",
                    Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * 1e3, v[0] * 1e3, v[1] * 1e3, v[2] * 1e3, e.tauS());
            case BASE_STEP -> String.format(Locale.ROOT, "Every measured point moved by one rigid motion at about %.0f s into the "
                    + "campaign, %.4f mm (%.4f, %.4f, %.4f mm along the base's axes) and a turn of %.1f µrad, the same whatever the "
                    + "arm's pose, and none of the known effects explains it: the instrument and the robot's base moved against each "
                    + "other (the instrument's stand knocked or a tripod's foot slipping, the base plate sliding on its anchors). The "
                    + "poses before it are modelled as seen from where the instrument then stood; it is not the robot's error and is "
                    + "left out of compensation. Check the instrument's stand and the base's anchors, and measure two or three fixed "
                    + "reference points (nests on the floor or the base) at the start and end of each campaign to see such a move.",
                    e.tauS(), Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * 1e3, v[0] * 1e3, v[1] * 1e3, v[2] * 1e3,
                    Math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]) * 1e6);
            case RANGE_STEP -> String.format(Locale.ROOT, "Every distance the instrument read changed by %.4f mm at about %.0f s into "
                    + "the campaign, along its line of sight, and none of the known effects explains it (a laser tracker takes the "
                    + "distance again from its absolute distance meter after its beam is broken, and that meter's error stays until "
                    + "the next break); it is the instrument, not the robot: keep the beam clear of the arm, or measure a fixed "
                    + "reference point after each break and before the next pose.", v[0] * 1e3, e.tauS());
            case ZERO_STEP -> String.format(Locale.ROOT, "Joint %d's zero jumped by %.4f deg at about %.0f s into the campaign "
                    + "and none of the known effects explains it (an encoder slip, a collision, a re-synchronisation); the poses "
                    + "before and after it do not belong to one robot: re-measure after checking the joint's zero.", e.joint() + 1,
                    Math.toDegrees(v[0]), e.tauS());
            case SETTLING -> String.format(Locale.ROOT, "Joint %d was read before it settled: its angle is off by %.3g ± %.2g "
                    + "mdeg per deg/s of its speed in the move just made (synchronised, the slowest joint setting the time), the way a "
                    + "residual vibration after the stop, or a servo's following error, leaves it, and none of the known effects "
                    + "explains it; it is no error of the robot at rest, so compensation leaves it out: wait longer after each stop "
                    + "before the reading.", e.joint() + 1, 1e3 * v[0], 1e3 * s[0]);
            case ZERO_DRIFT -> String.format(Locale.ROOT, "Joint %d's zero moves with %s (a smooth curve over %.4g..%.4g %s) and "
                    + "none of the known effects explains it; it is modelled as such, but compensation cannot use it without "
                    + "the %s and its cause is unknown (encoder slip or creep, a drive warming up).", e.joint() + 1,
                    e.along().words, e.rangeLo(), e.rangeHi(), e.along().unit, e.along().words);
            case THERMAL_LINK -> {
                StringBuilder sb = new StringBuilder("The arm grows with temperature link by link (thermal growth):");
                int nl = e.warms() ? v.length / 2 : v.length;
                for (int i = 0; i < nl; i++)
                    sb.append(String.format(Locale.ROOT, " %s %.3g ± %.2g /K%s", e.linkWords(i), v[i], s[i], i < nl - 1 ? "," : "."));
                if (e.warms()) {
                    sb.append(" The links also grow as the drives warm them while the robot works (time constant " + e.warmWords()
                            + (e.coolsInPauses() ? ", cooling toward the air while it stood " + e.pauseWords() : "")
                            + "), when warmed through:");
                    for (int i = nl; i < v.length; i++)
                        sb.append(String.format(Locale.ROOT, " %s %.1f ± %.1f ppm%s", e.linkWords(i - nl), 1e6 * v[i], 1e6 * s[i],
                                i < v.length - 1 ? "," : "."));
                }
                sb.append(String.format(Locale.ROOT, " Reference %.1f °C (steel is about 12e-6/K, aluminium 23e-6/K).", e.t0C()));
                yield sb.toString();
            }
            case DRIFT -> String.format(Locale.ROOT, "The measured points drift %s: %.4f mm per %s in the base frame (%.4f, %.4f, "
                    + "%.4f mm); the instrument or the robot's base moves. Compensation applies it only when the %s is given.",
                    e.usesTimeProxy() ? "with time" : "with temperature", 1e3 * Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]),
                    e.usesTimeProxy() ? "hour" : "K", 1e3 * v[0], 1e3 * v[1], 1e3 * v[2], e.usesTimeProxy() ? "time" : "temperature");
            case BACKLASH -> {
                String text = e.heldByGravity()
                    ? String.format(Locale.ROOT, "Joint %d has backlash of %.4f ± %.4f deg held on one flank by gravity except "
                    + "where the gravity torque on it is small: where the torque is above %.1f N·m%s (%s) the "
                    + "output sits half the play ahead in the direction gravity pushes it, whatever the last motion; below it "
                    + "the output lags the motor-side encoder by half the play behind the direction it last moved in%s "
                    + "(directions %s). The holding torque was chosen by the leave-one-pose-out error.", e.joint() + 1,
                    Math.toDegrees(v[0]), Math.toDegrees(s[0]), e.heldAboveNm(), e.heldWidth() > 0 ? String.format(Locale.ROOT,
                    " (handed over gradually from %.1f to %.1f N·m)", (1 - e.heldWidth()) * e.heldAboveNm(),
                    (1 + e.heldWidth()) * e.heldAboveNm()) : "", e.gravity().fromLengths() ? "the robot file has no masses: "
                    + "the arm's links taken as uniform beams of its lengths, so the torque is an estimate; give the robot file a "
                    + "mass_model" : "robot file's masses", at, dirs.words)
                    : e.buildsUp()
                    ? String.format(Locale.ROOT, "Joint %d has lost motion that builds up over the move (friction wind-up): after a "
                    + "long move its output lags the motor-side encoder by half of %.4f ± %.4f deg behind the direction it last "
                    + "moved in%s; after a shorter move the lag is smaller, reaching 63 %% of that after %.1f deg of travel "
                    + "(build-up length, chosen by the leave-one-pose-out error; Dahl's solid-friction model). Directions %s, "
                    + "move sizes from the joint values in the measuring order.%s Compensation does not know the next move's size "
                    + "and takes the full lag.", e.joint() + 1, Math.toDegrees(v[0]), Math.toDegrees(s[0]), at,
                    Math.toDegrees(e.buildUpRad()), dirs.words, e.approached() ? String.format(Locale.ROOT, " Each pose was "
                    + "approached from the side its direction records, by a move the file does not hold: where the move before "
                    + "it went the other way (or stopped short of the approach) the drive turned round short of the pose and its "
                    + "lag built up over the approach alone, where it went the same way over that move; the approach's length "
                    + "that predicts left-out poses best "
                    + "is %.1f deg in this model (friction laws differ in how much a short move unwinds, so compare it with the "
                    + "measuring program's approach rather than take it for that).", Math.toDegrees(e.approachRad())) : "")
                    : String.format(Locale.ROOT, "Joint %d has lost motion (backlash): its output lags the motor-side "
                    + "encoder by half of %.4f ± %.4f deg behind the direction it last moved in%s (directions %s).", e.joint() + 1,
                    Math.toDegrees(v[0]), Math.toDegrees(s[0]), at, dirs.words);
                if (e.runout()) text += runout(e, v);
                yield text;
            }
            case THERMAL -> e.usesTimeProxy()
                    ? String.format(Locale.ROOT, "The arm grows while it warms up (thermal expansion, inferred from time): "
                    + "strain %.3g ± %.2g at saturation, time constant %.0f s%s.", v[0], s[0], e.tauS(), e.coolsInPauses()
                    ? ", cooling toward the air while the robot stood " + e.pauseWords() + " (warmed by its drives, not by the air)" : "")
                    : String.format(Locale.ROOT, "The arm grows with temperature (thermal expansion): %.3g ± %.2g per K "
                    + "(steel is about 12e-6, aluminium 23e-6), reference %.1f °C.", v[0], s[0], e.t0C());
            case SCALE -> String.format(Locale.ROOT, "Joint %d turns by a slightly different amount than commanded (gear ratio "
                    + "or encoder scale error, or a spring that pulls the joint back in proportion to how far it has turned, such as "
                    + "a cable or hose winding with it): %.3g ± %.2g.", e.joint() + 1, v[0], s[0]);
            case COUPLING -> String.format(Locale.ROOT, "Joint %d moves a little with joint %d (coupling error between the axes): "
                    + "%.3g ± %.2g rad per rad.", e.joint() + 1, e.source() + 1, v[0], s[0]);
        };
        if (e.kind() == Effect.Kind.COMPLIANCE && e.atJoint()) what += String.format(Locale.ROOT, " The give is of joint %d's own angle, by the torque "
                + "about its axis of everything beyond it, not of drive %d's gear: through the linkage it turns the arm beyond "
                + "the joint, the parts other drives hold included (the joint's bearing or its housing, or a serial model of the "
                + "joint's stiffness); it fits these poses better than a spring in the drive's gear.", e.joint() + 1, e.joint() + 1);
        if (e.kind() == Effect.Kind.BASE_TILT) what += pivotWords(v, s);
        String fit = String.format(Locale.ROOT, " Modelling it lowers the training RMS from %.4f to %.4f mm", trainBefore * 1e3,
                trainAfter * 1e3);
        if (Double.isFinite(valBefore)) fit += String.format(Locale.ROOT, " and the validation RMS from %.4f to %.4f mm", valBefore * 1e3, valAfter * 1e3);
        fit += String.format(Locale.ROOT, " (F = %.1f on %d and %d degrees of freedom, p = %.2g below the corrected "
                + "threshold %.2g; leave-one-out prediction error %.1f -> %.1f; %s).", ev.f(), ev.df1(), ev.df2(), ev.pValue(),
                ev.threshold(), ev.pressBefore(), ev.pressAfter(), ev.plausibility());
        return what + fit;
    }

    /**
     * Why a link's bending and the spring of its own joint are not told apart: the spring's fit predicts
     * left-out poses within the alias margin of the bending's ({@code pressSpring} against {@code pressOwn}).
     */
    static String springAlike(Effect sag, Effect spring, double pressSpring, double pressOwn, boolean sixD) {
        return String.format(Locale.ROOT, "Joint %d's spring (%s) predicts left-out poses as well (leave-one-pose-out error %.1f "
                + "against %.1f), and these poses cannot tell the two apart: a spring turns the whole link about its joint, moving "
                + "its far end by L·θ as it turns it by θ, a beam moves its far end by 2/3 to 3/4 of that, and what differs is "
                + "small beside the noise here. An industrial arm's links are usually much stiffer than its geared joints, so "
                + "the joint is the likelier of the two. It is modelled as the bending so compensation can use it (both predict "
                + "alike here), and neither is claimed. To tell them apart, measure %sa target on the %s's far end (on joint %d's "
                + "housing), with two or three payloads.", sag.joint() + 1, spring.label(), pressSpring, pressOwn,
                sixD ? "" : "the flange's orientation as well as its position (6-D), and ", linkName(sag), sag.joint() + 2);
    }

    /** The link a link sag bends: "upper arm" (joint 2's) or "forearm" (joint 3's). */
    private static String linkName(Effect sag) { return sag.joint() == 1 ? "upper arm" : "forearm"; }

    /**
     * On a joint sampled over less than three quarters of a turn, two harmonics closer than 360°/range cycles per turn
     * cannot be told apart (the frequency resolution of a record of that length), and a few
     * stage harmonics look like a place-bound shape: a smooth error found there may be a
     * multi-stage or cycloidal reducer's transmission error that these poses cannot resolve.
     */
    static String shortRange(Effect e) {
        double range = e.rangeHi() - e.rangeLo();
        if (!(range < 1.5 * Math.PI)) return "";
        return String.format(Locale.ROOT, " Over a range of %.0f deg, harmonics of the joint closer than %.1f cycles per turn "
                + "cannot be told apart, so a multi-stage or cycloidal reducer's stage harmonics cannot be told from such a "
                + "shape here: if joint %d has such a reducer, this may be its transmission error; measure the joint over as "
                + "much of a turn as its limits allow, with at least 5 poses per cycle of the highest stage, to tell.",
                Math.toDegrees(range), 2 * Math.PI / range, e.joint() + 1);
    }

    static String fmtList(double[] v) {
        List<String> out = new ArrayList<>();
        for (double x : v) out.add(String.format(Locale.ROOT, "%.3g", x));
        return "[" + String.join(", ", out) + "]";
    }

    /** RMS of an instrument-reading error over the readings' range: its spline's, or a cycle's amplitude over √2. */
    static double rmsInstrument(Effect e, double[] v) {
        if (!Double.isFinite(e.cycle())) return rmsCurve(e, v);
        double s = 0;
        for (double x : v) s += x * x;
        return Math.sqrt(s / 2); // the harmonics are orthogonal over a whole cycle
    }

    /** RMS over its range of a spline effect's curve, its mean included (an instrument's offset is part of its error). */
    static double rmsCurve(Effect e, double[] v) {
        int n = 200;
        double[] g = new double[e.basisCount()];
        double s = 0;
        for (int i = 0; i < n; i++) {
            Effect.bspline(e.rangeLo() + (e.rangeHi() - e.rangeLo()) * i / (n - 1.0), e.rangeLo(), e.rangeHi(), g);
            double y = 0;
            for (int k = 0; k < g.length; k++) y += g[k] * v[k];
            s += y * y;
        }
        return Math.sqrt(s / n);
    }

    /**
     * RMS of a smooth error's curve over its range about its mean, rad: the angle-dependent part.
     * A constant is the joint's zero, which the geometry holds (with lengths between pairs of poses
     * the spline's constant is only nearly the zero's and can come out large and uncertain).
     */
    static double rmsSmooth(Effect e, double[] v) {
        int n = 200;
        double[] g = new double[e.basisCount()], y = new double[n];
        double mean = 0;
        for (int i = 0; i < n; i++) {
            Effect.bspline(e.rangeLo() + (e.rangeHi() - e.rangeLo()) * i / (n - 1.0), e.rangeLo(), e.rangeHi(), g);
            for (int k = 0; k < g.length; k++) y[i] += g[k] * v[k];
            mean += y[i] / n;
        }
        double s = 0;
        for (double yi : y) s += (yi - mean) * (yi - mean);
        return Math.sqrt(s / n);
    }

    /**
     * RMS over a circle of a form linear in the cosine and sine of its angle, √(Σ v² / 2): an axis
     * wobble's tilt across the axis over a turn (rad; each order's four coefficients share
     * (x² + y²) / 2), an axial runout's shift along it (m), a tool play's move across the tool's axis
     * over the directions it is pulled to (m; B·u with u on the unit circle).
     */
    /**
     * Where a tool pull's fit says the force points: toward its anchor, or, for a pull of one direction,
     * the direction (base frame) of the largest singular vector of its joints' coefficients c_j F (a
     * single force seen by every joint), signed so the joints' compliances come out positive.
     */
    static String pullWhere(Effect e, double[] v) {
        double[] a = e.pullAnchor();
        if (a != null) return String.format(Locale.ROOT, "toward a fixed point at (%.2f, %.2f, %.2f) m in the base frame", a[0], a[1], a[2]);
        double[] u = pullAxis(v);
        if (u == null) return "in no one direction";
        return String.format(Locale.ROOT, "along (%.2f, %.2f, %.2f) in the base frame (%.0f deg from straight up, toward azimuth %.0f deg)",
                u[0], u[1], u[2], Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, u[2])))), Math.toDegrees(Math.atan2(u[1], u[0])));
    }

    /**
     * The direction (unit, base frame) of the one force a tool pull's coefficients c_j F (three per
     * joint) share best: their largest singular vector, signed so the compliances come out positive;
     * null when they are all zero.
     */
    static double[] pullAxis(double[] v) {
        int n = v.length / 3;
        double[] m = new double[9];
        for (int j = 0; j < n; j++) for (int r = 0; r < 3; r++) for (int c = 0; c < 3; c++) m[3 * r + c] += v[3 * j + r] * v[3 * j + c];
        double[] u = {1, 1, 1};
        for (int it = 0; it < 100; it++) {
            double[] w = new double[3];
            for (int r = 0; r < 3; r++) for (int c = 0; c < 3; c++) w[r] += m[3 * r + c] * u[c];
            double nn = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            if (!(nn > 0)) return null;
            for (int r = 0; r < 3; r++) u[r] = w[r] / nn;
        }
        double sum = 0;
        for (int j = 0; j < n; j++) sum += v[3 * j] * u[0] + v[3 * j + 1] * u[1] + v[3 * j + 2] * u[2];
        if (sum < 0) for (int r = 0; r < 3; r++) u[r] = -u[r];
        return u;
    }

    static double rmsOverCircle(double[] v) {
        double s = 0;
        for (double x : v) s += x * x;
        return Math.sqrt(s / 2);
    }

    /**
     * How much more a tool sag's point drops toward gravity with its holder turned to its softest
     * direction than to its stiffest, m: gravity seen from the flange ĝ_f moves the point toward
     * gravity by ĝ_fᵀ·A·ĝ_f, which over ĝ_f spans the eigenvalues of A's symmetric part (a holder's
     * compliance is symmetric, Maxwell-Betti); their spread (a bar: its sag held across gravity,
     * against none along it). An isotropic part is a constant shift the geometry holds.
     */
    static double sagSpan(double[] v) {
        DMatrixRMaj a = new DMatrixRMaj(3, 3);
        for (int r = 0; r < 3; r++) for (int c = 0; c < 3; c++) a.set(r, c, (v[3 * r + c] + v[3 * c + r]) / 2);
        EigenDecomposition_F64<DMatrixRMaj> eig = DecompositionFactory_DDRM.eig(3, false, true);
        if (!eig.decompose(a)) return Double.NaN;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < 3; i++) { double l = eig.getEigenvalue(i).real; lo = Math.min(lo, l); hi = Math.max(hi, l); }
        return hi - lo;
    }

    private static String wobbleOrders(Effect e) {
        int[] h = e.harmonics();
        if (h.length == 1) return h[0] == 1 ? "once per turn" : h[0] + " times per turn";
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < h.length; i++) b.append(i == 0 ? "" : i == h.length - 1 ? " and " : ", ").append(h[i]);
        return b + " times per turn";
    }

    static String p(double p) { return p < 1e-300 ? "< 1e-300" : String.format(Locale.ROOT, "= %.2g", p); }

    static String implausible(Effect e, double[] v, Diagnosis.Evidence ev) {
        return String.format(Locale.ROOT, "%s would reduce the residuals significantly (F = %.1f, p = %.2g), but its estimate "
                + "is physically implausible (%s), so it is not claimed: the residual structure it fits probably has another "
                + "cause.", e.label(), ev.f(), ev.pValue(), ev.plausibility()).replace("p = 0,", "p < 1e-300,");
    }

    /** The instrument's distances scaling with time or temperature: the scale's change from one end of the range to the other. */
    private static String instrumentScale(Effect e, double[] v, String at) {
        boolean time = e.along() == Effect.Along.TIME;
        double grown = e.splineAt(v, 0, e.rangeHi()) - e.splineAt(v, 0, e.rangeLo());
        return String.format(Locale.ROOT, "The measured positions scale about the instrument with %s: from %.4g to %.4g %s its "
                + "distances' scale changes by %+.2f ppm%s (a constant scale is the geometry's). No error of the robot "
                + "explains it, and the robot growing with the instrument moving toward it would hold it only together: the "
                + "instrument's distance meter, whose air compensation (the air's temperature, pressure and humidity, about 1 ppm "
                + "per kelvin or per 3.7 hPa) drifted from the air the beam went through. It is modelled so that it does not bend "
                + "the robot's fit, and left out of compensation: check the instrument's weather station against a calibrated "
                + "thermometer and barometer at the beam's height, keep it out of drafts and sunlight, and re-measure a known "
                + "length (a scale bar) every few poses.", time ? "time" : "temperature", e.rangeLo(), e.rangeHi(), e.along().unit,
                1e6 * grown, at);
    }

    /** Refractivity of room air, n − 1 (about 20 °C, 1013 hPa; Edlén). */
    private static final double AIR_REFRACTIVITY = 2.7e-4;

    /** The instrument's beam bent by the air's temperature gradient: the change of the gradient it implies over the range. */
    private static String refraction(Effect e, double[] v) {
        double dk = e.splineAt(v, 0, e.rangeHi()) - e.splineAt(v, 0, e.rangeLo());
        // k = κ/2 and κ = (n − 1)/T · dT/dz: the gradient's change at 293 K
        double dGrad = 2 * dk * 293.15 / AIR_REFRACTIVITY;
        return String.format(Locale.ROOT, "The measured points are seen moved up or down by the square of their horizontal distance "
                + "from the instrument, by an amount that changes with %s: from %.4g to %.4g %s it changes by %+.3g µm at 10 m (a "
                + "constant part the geometry holds). No error of the robot moves points so: the instrument's beam bent by the air, "
                + "whose vertical temperature gradient changed by about %+.2f K/m (warm air above cool bends the beam down and the "
                + "points are seen higher). It is modelled so that it does not bend the robot's fit, and left out of compensation: "
                + "measure the air's temperature at two heights along the beam, keep the hall's air mixed and the instrument closer "
                + "to the robot, or let the hall settle before measuring.", e.along().words, e.rangeLo(), e.rangeHi(), e.along().unit,
                dk * 100 * 1e6, dGrad);
    }

    /** A base or instrument turning with time or temperature: its turn and move from one end of the range to the other. */
    private static String baseTurn(Effect e, double[] v) {
        int nb = e.basisCount();
        double[] w = new double[3];
        for (int a = 0; a < 3; a++) w[a] = e.splineAt(v, a * nb, e.rangeHi()) - e.splineAt(v, a * nb, e.rangeLo());
        double tilt = Math.hypot(w[0], w[1]), move = Math.sqrt(v[3 * nb] * v[3 * nb] + v[3 * nb + 1] * v[3 * nb + 1] + v[3 * nb + 2] * v[3 * nb + 2]);
        boolean time = e.along() == Effect.Along.TIME;
        return String.format(Locale.ROOT, "The robot's base or the instrument turns with %s: from %.4g to %.4g %s it tilts by %.1f µrad "
                + "about a horizontal axis at %.0f deg from the base's x axis and turns by %.1f µrad about the vertical, and moves by "
                + "%.4f mm; none of the known effects explains it (a floor slab or the instrument's stand tilting as it warms or "
                + "settles). It is modelled as such so compensation can use it, but its cause is unknown: re-measure a fixed "
                + "reference point every few poses and read the instrument's level before and after.", time ? "time" : "temperature",
                e.rangeLo(), e.rangeHi(), e.along().unit, 1e6 * tilt, Math.toDegrees(Math.atan2(w[1], w[0])), 1e6 * w[2], 1e3 * move);
    }

    /**
     * A play that changes over the turn, in words: its least and largest width over the turn and
     * where it is widest (values b, b_cos, b_sin in rad), and what turns at its order.
     */
    static String runout(Effect e, double[] v) {
        double[] f = e.runoutOrders();
        int jn = e.joint() + 1;
        if (f.length == 1 && f[0] == 1) {
            double change = Math.hypot(v[1], v[2]), widest = Math.toDegrees(Math.atan2(v[2], v[1]));
            return String.format(Locale.ROOT, " Its play changes over the turn of joint %d, from %.4f to %.4f deg, widest at q%d = %.0f deg: "
                    + "an output gear running off its bearing's centre (runout) moves closer to its pinion and away once per turn, and "
                    + "the play between their teeth changes with that distance (chosen by the leave-one-pose-out error; to confirm it, "
                    + "approach the joint from both sides at several angles over its range and compare the lag).", jn,
                    Math.toDegrees(v[0] - change), Math.toDegrees(v[0] + change), jn, widest);
        }
        // the least and largest play over a turn, on a grid fine enough for the highest order
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        int n = (int) Math.ceil(64 * f[f.length - 1]);
        for (int i = 0; i < n; i++) {
            double b = Effect.play(f, v, -Math.PI + 2 * Math.PI * i / n);
            lo = Math.min(lo, b);
            hi = Math.max(hi, b);
        }
        List<String> parts = new ArrayList<>();
        for (int i = 0; i < f.length; i++)
            parts.add(String.format(Locale.ROOT, "%.4f deg %s", Math.toDegrees(Math.hypot(v[1 + 2 * i], v[2 + 2 * i])),
                    f[i] == 1 ? "once per turn (the output gear running off its bearing's centre)"
                    : Effect.orderText(f[i]) + " times per turn (a gear of the last stage turning that often per output turn, a pinion "
                    + "meshing with the output gear: z_gear/z_pinion)"));
        double top = f[f.length - 1];
        return String.format(Locale.ROOT, " Its play changes over the turn of joint %d, between %.4f and %.4f deg: by %s. A gear running "
                + "off its centre moves closer to its mate and away once per its own turn, and the play between their teeth changes with "
                + "that distance (an order that is not whole found in the lag's spectrum; each chosen by the leave-one-pose-out error). "
                + "To confirm it, approach the joint from both sides at angles %.1f deg apart, half a cycle of the fastest, and compare "
                + "the lag, and check the stage's tooth counts.", jn, Math.toDegrees(lo), Math.toDegrees(hi), String.join(", and ", parts),
                180 / top);
    }

    /** A stiffness 1/c in kN·m/rad as text; "none" where the compliance is not positive. */
    /**
     * A periodic error whose size follows a share (the load's, the temperature's) with its values
     * {@code v}: n sine and cosine pairs at no share, then n pairs of their change; the squared sums of
     * each half (root them for the amplitudes over the orders, root-sum-square).
     */
    static double[] sizeAndChange(double[] v, int n) {
        double at0 = 0, per = 0;
        for (int i = 0; i < n; i++) {
            at0 += v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1];
            per += v[2 * n + 2 * i] * v[2 * n + 2 * i] + v[2 * n + 2 * i + 1] * v[2 * n + 2 * i + 1];
        }
        return new double[] {at0, per};
    }

    /**
     * The payload's centre as a varying compliance with it estimated puts it: each time function's
     * columns are the torque at the file's centre and its change per {@link GravityTorques#PAYLOAD_SHIFT_M}
     * along the flange's axes, so the shift is the ratio of their sums over the functions.
     */
    static String payloadCentreText(double[] v) {
        double c = 0;
        double[] d = new double[3];
        for (int i = 0; i + 3 < v.length; i += 4) { c += v[i]; for (int k = 0; k < 3; k++) d[k] += v[i + k + 1]; }
        if (c == 0) return "";
        return String.format(Locale.ROOT, "The payload's centre of mass was estimated with it: (%.0f, %.0f, %.0f) mm from where the robot "
                + "file puts it, along the flange's x, y and z. ", d[0] / c * GravityTorques.PAYLOAD_SHIFT_M * 1e3,
                d[1] / c * GravityTorques.PAYLOAD_SHIFT_M * 1e3, d[2] / c * GravityTorques.PAYLOAD_SHIFT_M * 1e3);
    }

    private static String stiffnessText(double c) {
        return c > 0 ? String.format(Locale.ROOT, "%.0f", 1e-3 / c) : "none (the fit's compliance is not positive)";
    }
}
