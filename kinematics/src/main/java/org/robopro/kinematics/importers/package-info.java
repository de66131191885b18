/**
 * Importers of other robot formats into robot descriptions: Denavit-Hartenberg tables (classic
 * and modified) and URDF.
 */
package org.robopro.kinematics.importers;
