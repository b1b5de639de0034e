// SPDX-License-Identifier: MIT
package org.orbillum.peers;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.DoubleBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Arrays;

import org.hipparchus.CalculusFieldElement;
import org.hipparchus.geometry.euclidean.threed.FieldVector3D;
import org.hipparchus.geometry.euclidean.threed.Vector3D;
import org.orekit.forces.radiation.ConicallyShadowedLightFluxModel;
import org.orekit.frames.Frame;
import org.orekit.time.AbsoluteDate;
import org.orekit.time.FieldAbsoluteDate;
import org.orekit.utils.ExtendedPositionProvider;

/**
 * Orekit's conical lighting ratio (ConicallyShadowedLightFluxModel, Orekit 12.2: the
 * Montenbruck and Gill planar two-circle overlap with its own umbra and penumbra cone
 * tests) over the points of a file, timed in one loop.
 *
 * Usage: java -cp ... org.orbillum.peers.OrekitLighting POINTS FRACTIONS [REPS [WARMUP]]
 *   POINTS     little-endian doubles, 6 a row: Sun x, y, z, target x, y, z (km, the Earth
 *              at the origin), as bench/peers.py writes them
 *   FRACTIONS  written: one little-endian double a row, the lighting ratio
 *   REPS       timed passes over all rows (default 15), after WARMUP untimed ones (default 5)
 * Prints "rows N", "ns_median X", "ns_best X" (ns per row of one pass).
 *
 * The pass calls the model's lighting ratio of a position and a Sun position (both
 * Vector3D, metres, built from the arrays in the loop as a caller holding arrays would);
 * it needs no Orekit data (no date, frame or ephemeris is read on that path).
 */
public final class OrekitLighting {

    /** Solar radius (m), IAU 2015 Resolution B3 nominal, as orbillum's OI_SUN_RADIUS_KM. */
    static final double R_SUN_M = 695700.0e3;
    /** Earth equatorial radius (m), WGS-84, as orbillum's OI_EARTH_RADIUS_KM. */
    static final double R_EARTH_M = 6378137.0;

    /** The Sun's position comes with each row: this provider is never asked. */
    static final class NoProvider implements ExtendedPositionProvider {
        @Override
        public <T extends CalculusFieldElement<T>> FieldVector3D<T> getPosition(final FieldAbsoluteDate<T> date,
                                                                                final Frame frame) {
            throw new UnsupportedOperationException("the harness passes the Sun's position per row");
        }

        @Override
        public Vector3D getPosition(final AbsoluteDate date, final Frame frame) {
            throw new UnsupportedOperationException("the harness passes the Sun's position per row");
        }
    }

    /** The model, its ratio of a position and a Sun position made callable here. */
    static final class Conical extends ConicallyShadowedLightFluxModel {
        Conical() {
            super(R_SUN_M, new NoProvider(), R_EARTH_M);
        }

        double ratio(final Vector3D position, final Vector3D sun) {
            return getLightingRatio(position, sun);
        }
    }

    private OrekitLighting() {
    }

    static double pass(final Conical model, final double[] p, final double[] out) {
        final int n = out.length;
        double sum = 0.0;
        for (int i = 0; i < n; i++) {
            final int k = 6 * i;
            final Vector3D sun = new Vector3D(p[k] * 1e3, p[k + 1] * 1e3, p[k + 2] * 1e3);
            final Vector3D pos = new Vector3D(p[k + 3] * 1e3, p[k + 4] * 1e3, p[k + 5] * 1e3);
            out[i] = model.ratio(pos, sun);
            sum += out[i];
        }
        return sum; // read, so that the loop is not dropped
    }

    public static void main(final String[] args) throws IOException {
        if (args.length < 2) {
            System.err.println("usage: OrekitLighting POINTS FRACTIONS [REPS [WARMUP]]");
            System.exit(2);
        }
        final int reps = args.length > 2 ? Integer.parseInt(args[2]) : 15;
        final int warmup = args.length > 3 ? Integer.parseInt(args[3]) : 5;
        final byte[] raw = Files.readAllBytes(Paths.get(args[0]));
        if (raw.length == 0 || raw.length % 48 != 0) {
            System.err.println("OrekitLighting: " + args[0] + ": not a whole number of 6-double rows");
            System.exit(2);
        }
        final DoubleBuffer db = ByteBuffer.wrap(raw).order(ByteOrder.LITTLE_ENDIAN).asDoubleBuffer();
        final double[] p = new double[db.remaining()];
        db.get(p);
        final int n = p.length / 6;
        final double[] out = new double[n];
        final Conical model = new Conical();
        double check = 0.0;
        for (int r = 0; r < warmup; r++) {
            check += pass(model, p, out);
        }
        final double[] t = new double[reps];
        for (int r = 0; r < reps; r++) {
            final long t0 = System.nanoTime();
            check += pass(model, p, out);
            t[r] = (System.nanoTime() - t0) / (double) n;
        }
        Arrays.sort(t);
        final ByteBuffer ob = ByteBuffer.allocate(8 * n).order(ByteOrder.LITTLE_ENDIAN);
        ob.asDoubleBuffer().put(out);
        final Path dst = Paths.get(args[1]);
        Files.write(dst, ob.array());
        System.out.println("rows " + n);
        System.out.println("ns_median " + t[reps / 2]);
        System.out.println("ns_best " + t[0]);
        System.out.println("checksum " + check);
    }
}
