package org.robopro.models;

import java.util.List;

/**
 * Optional mass model: link masses, the rated payload and where a payload's centre of mass sits
 * on the flange (flange coordinates, m). Gravity acts along -z of the base unless {@code gravity}
 * says otherwise (m/s^2, base coordinates).
 */
public record MassModel(List<LinkMass> links, double ratedPayloadKg, Vec3 payloadCentreOfMass, Vec3 gravity) {
    public MassModel {
        links = List.copyOf(links);
    }
}
