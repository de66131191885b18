/**
 * Robot and cell descriptions as the files give them, and the file handling every module shares:
 * robot files ({@link org.robopro.models.RobotFile}, the shipped robots of
 * {@link org.robopro.models.RobotLibrary}), cell files, JSON with source positions, UTF-8 text
 * reading ({@link org.robopro.models.TextFiles}), whole-or-nothing output
 * ({@link org.robopro.models.AtomicFiles}, {@link org.robopro.models.OutputSet}) and the one
 * error type for bad user input, {@link org.robopro.models.InputException} (file, line, field).
 * Plain immutable data; no kinematics. The bottom of the module graph.
 */
package org.robopro.models;
