/**
 * The 3D view (jMonkeyEngine): one AppState per feature (environment, robot, cell, path, camera,
 * selection), updated from the model each frame; meshes and procedural shapes.
 */
package org.robopro.app.workbench.scene;
