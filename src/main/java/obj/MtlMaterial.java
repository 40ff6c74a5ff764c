package obj;

import primitives.Color;
import primitives.Double3;
import primitives.Material;

/**
 * One {@code newmtl} of an MTL file as written (unset statements null), and its mapping onto the library's
 * {@link Material} and emission, documented with a table in docs/SCENE-FORMAT.md:
 *
 * <ul>
 *   <li>{@code Kd}, {@code Ks}, {@code Ka} become kD, kS, kA; {@code Ns} the shininess (rounded); {@code Ke}
 *       the emission, times 255 (MTL's colours are 0..1, the library's light 0..255).
 *   <li>{@code d} (or {@code 1 - Tr}) below 1 makes the surface partly see-through: kT = 1 - d, and kD and kA are
 *       scaled by d so the surface plus what shows through it stays within the light that arrives.
 *   <li>{@code illum} 3 to 8 reflect as a mirror with kR = Ks; 6 and 7 (refraction on) bend light by {@code Ni},
 *       the others go straight through (index 1); 1 has no highlight (kS = 0); 0 is unlit: the colour Kd shown as
 *       emission; 9 is transparency without reflection; 2, 10 and no illum are plain Phong.
 * </ul>
 *
 * @param name the material's name ({@code newmtl})
 * @param file the MTL file's name, for messages
 * @param line the line of {@code newmtl}
 * @param kd diffuse colour {@code Kd}, or null
 * @param ks specular colour {@code Ks}, or null
 * @param ka ambient colour {@code Ka}, or null
 * @param ke emissive colour {@code Ke}, or null
 * @param ns specular exponent {@code Ns}, or null
 * @param ni optical density (index of refraction) {@code Ni}, or null
 * @param dissolve opacity {@code d} (or {@code 1 - Tr}), 0 to 1, or null
 * @param illum illumination model 0 to 10, or null
 * @param mapKd the diffuse texture {@code map_Kd}, or null
 */
public record MtlMaterial(
        String name,
        String file,
        int line,
        Double3 kd,
        Double3 ks,
        Double3 ka,
        Double3 ke,
        Double ns,
        Double ni,
        Double dissolve,
        Integer illum,
        TextureMap mapKd) {

    /**
     * A texture statement ({@code map_Kd}): the image file relative to the MTL file's folder and how it wraps.
     *
     * @param file the image file as written
     * @param clamp true for {@code -clamp on} (edge texels extend), false to repeat (the default)
     * @param line the line of the statement, for messages
     */
    public record TextureMap(String file, boolean clamp, int line) {}

    /**
     * The library material these values describe (without a texture: the caller loads {@link #mapKd()}).
     *
     * @return a new material
     */
    public Material toMaterial() {
        Material m = new Material();
        int model = illum == null ? 2 : illum;
        double d = dissolve == null ? 1 : dissolve;
        Double3 diffuse = kd == null ? Double3.ZERO : kd;
        Double3 specular = ks == null ? Double3.ZERO : ks;
        if (model == 0) return m.setKa(0); // unlit: the colour is the emission
        m.setKd(diffuse.scale(d));
        if (ka != null) m.setKa(ka.scale(d));
        else if (d < 1) m.setKa(d);
        if (model != 1) m.setKs(specular);
        if (ns != null) m.setShininess((int) Math.round(ns));
        if (model >= 3 && model <= 8) m.setKr(specular);
        if (d < 1) m.setKt(1 - d);
        if ((model == 6 || model == 7) && ni != null) m.setIndexOfRefraction(ni);
        return m;
    }

    /**
     * The light the surface gives off: {@code Ke} times 255, or for {@code illum 0} (unlit) the colour Kd.
     *
     * @return the emission, black when none
     */
    public Color emission() {
        Double3 e = illum != null && illum == 0 ? kd : ke;
        if (e == null) return Color.BLACK;
        return new Color(255 * e.d1, 255 * e.d2, 255 * e.d3);
    }
}
