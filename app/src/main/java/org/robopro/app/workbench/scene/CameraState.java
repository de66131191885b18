package org.robopro.app.workbench.scene;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;

/**
 * Orbit / pan / zoom navigation around a focus point, and the standard views. Angles in robot
 * (z-up) terms: azimuth about world z from +x, elevation above the floor. The Swing thread sets
 * the wanted view through the synchronized setters; the camera is moved on the render thread.
 */
public final class CameraState extends BaseAppState {
    /** The standard views: from the front (+x), the top, the robot's left side (+y) and an isometric view. */
    public enum View { FRONT, TOP, SIDE, ISO }

    private double azimuth = Math.toRadians(-35), elevation = Math.toRadians(24), distance = 4.3;
    private double fx = 0.8, fy = 0, fz = 0.8;
    private boolean changed = true;

    public synchronized void orbit(double dAzimuth, double dElevation) {
        azimuth += dAzimuth;
        elevation = Math.max(Math.toRadians(-89), Math.min(Math.toRadians(89.9), elevation + dElevation));
        changed = true;
    }

    /** Moves the focus in the view plane; dx, dy as fractions of the view height. */
    public synchronized void pan(double dx, double dy) {
        double s = distance * 0.8;
        double ca = Math.cos(azimuth), sa = Math.sin(azimuth), se = Math.sin(elevation), ce = Math.cos(elevation);
        // camera right = (-sin a, cos a, 0) ; camera up = (-cos a sin e, -sin a sin e, cos e)
        fx += s * (-dx * -sa + dy * -ca * se);
        fy += s * (-dx * ca + dy * -sa * se);
        fz += s * (dy * ce);
        changed = true;
    }

    public synchronized void zoom(double factor) {
        distance = Math.max(0.2, Math.min(60, distance * factor));
        changed = true;
    }

    public synchronized void focus(double x, double y, double z) {
        fx = x; fy = y; fz = z;
        changed = true;
    }

    public synchronized void view(View v) {
        switch (v) {
            case FRONT -> { azimuth = 0; elevation = Math.toRadians(5); }
            case TOP -> { azimuth = Math.toRadians(-90); elevation = Math.toRadians(89.9); }
            case SIDE -> { azimuth = Math.toRadians(-90); elevation = Math.toRadians(5); }
            case ISO -> { azimuth = Math.toRadians(-35); elevation = Math.toRadians(24); }
        }
        changed = true;
    }

    /** Camera position in robot (z-up) coordinates. */
    public synchronized double[] eye() {
        double ce = Math.cos(elevation);
        return new double[] {fx + distance * ce * Math.cos(azimuth), fy + distance * ce * Math.sin(azimuth),
                fz + distance * Math.sin(elevation)};
    }

    @Override protected void initialize(Application app) { }
    @Override protected void cleanup(Application app) { }
    @Override protected void onEnable() { changed = true; }
    @Override protected void onDisable() { }

    @Override
    public void update(float tpf) {
        double[] e;
        double[] f;
        synchronized (this) {
            if (!changed) return;
            changed = false;
            e = eye();
            f = new double[] {fx, fy, fz};
        }
        Camera cam = getApplication().getCamera();
        cam.setFrustumPerspective(40f, (float) cam.getWidth() / Math.max(1, cam.getHeight()), 0.05f, 200f);
        cam.setLocation(zUpToJme(e));
        cam.lookAt(zUpToJme(f), Vector3f.UNIT_Y);
    }

    /** Call when the view was resized so the aspect ratio is refreshed. */
    public synchronized void refresh() { changed = true; }

    /** robot (x, y, z) -> jME (x, z, -y): the scene's world node turns z-up into jME's y-up. */
    public static Vector3f zUpToJme(double[] p) { return new Vector3f((float) p[0], (float) p[2], (float) -p[1]); }

}
