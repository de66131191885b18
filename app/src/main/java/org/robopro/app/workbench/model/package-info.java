/**
 * The workbench's application model: the cell, the robot's kinematics as drawn and jogged, tools,
 * work objects, targets, the program being edited and its background path check, and the edit
 * history. Plain objects; the scene and the panels are updated from them.
 */
package org.robopro.app.workbench.model;
