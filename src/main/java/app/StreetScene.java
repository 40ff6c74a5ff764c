package app;

import geometries.Accelerator;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
import geometries.Plane;
import geometries.Polygon;
import geometries.Prototype;
import geometries.Sphere;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import renderer.RenderSettings;
import renderer.sampling.SamplingConfig;
import renderer.sampling.SamplingPattern;
import renderer.sampling.TargetShape;
import scene.Scene;

/**
 * A street at night, defined once for the tests, benchmarks and the CLI: a wet road with markings, puddles and a
 * zebra crossing between kerbed sidewalks, two rows of houses with lit windows, shop fronts and neon signs, houses
 * closing the far end, trees, ten street lamps (posts with glowing glass globes, each a point light that becomes a
 * disk light for soft shadows), a bus shelter with a glass roof, an illuminated advert, a bench and a spot light,
 * another bench, two parked cars built as triangle meshes, stars, and a rising moon (an emissive sphere far away,
 * with maria) with its moonlight. {@link #primitiveCount()} counts the primitives the renderer sees.
 *
 * <p>Units are 5 cm: the lamps stand 7 m tall, the road is 14 m wide. The street runs along +y, z is up; the
 * camera stands on the road looking down the street toward the moon. Everything random (building sizes, which
 * windows are lit) comes from a fixed seed, so every build is identical.
 */
public final class StreetScene {
    /** Where the camera stands, what it looks at, and its view-plane distance and width (height follows the image). */
    public static final Point CAMERA_LOCATION = new Point(-30, -420, 85);

    /** The point the camera looks at. */
    public static final Point CAMERA_TARGET = new Point(5, 1200, 150);
    /** The view plane's distance from the camera and its width, in scene units. */
    public static final double VP_DISTANCE = 300, VP_WIDTH = 320;

    /** Half-width of the road; the kerb stones and sidewalks run outward from it to the house fronts. */
    static final double ROAD = 140, KERB = 146, FACADE = 250, SIDEWALK_TOP = 3;

    static final double STREET_START = -800, STREET_END = 5600;
    /**
     * Colour difference (0..255 scale) above which adaptive anti-aliasing refines a pixel: about the smallest step
     * visible in the dark parts of the picture.
     */
    public static final double ADAPTIVE_THRESHOLD = 6;

    private static final double MOON_DISTANCE = 60_000, MOON_RADIUS = 1300;
    /**
     * Street lamps: a post with a glass globe, the light 143 up, 3 above the globe's centre. The globe is clear glass
     * of transparency 1 (index 1: a thin shell), so the shadow rays leaving it keep a transmittance of exactly 1; glass
     * of kT below 1 would make every point of the street look like a penumbra to adaptive shadow sampling.
     */
    private static final double LAMP_HEIGHT = 143, GLOBE_RADIUS = 15, GLOBE_CENTRE = LAMP_HEIGHT - 3, GLOBE_KT = 1;

    private final StreetOptions options;
    private final Scene scene;
    private final List<Landmark> lampGlobes = new ArrayList<>();
    private final List<Landmark> litWindows = new ArrayList<>();
    private final Random random = new Random(20240917L);
    private Sphere moon;

    /**
     * Builds the street with the given lamp settings.
     *
     * @param options the lamps' radius and samples
     */
    public StreetScene(StreetOptions options) {
        this.options = options;
        this.scene = new Scene("street")
                .setBackground(new Color(5, 8, 20))
                .setAmbientLight(new AmbientLight(new Color(26, 30, 48), 1));
        addGround();
        addHouses(1);
        addHouses(-1);
        addEndOfStreet();
        addLamps();
        addTrees();
        addShelter(new Point(182, 330, SIDEWALK_TOP));
        scene.geometries.add(BenchModel.build(new Point(-226, 330, SIDEWALK_TOP), 1));
        scene.geometries.add(CarModel.build(new Point(-110, 250, 0), 1, new Color(150, 18, 24)));
        scene.geometries.add(CarModel.build(new Point(112, 1010, 0), -1, new Color(30, 60, 120)));
        addPuddles();
        addMoon();
    }

    /**
     * Renders the street into {@code images/street-render.png}: {@code [width height aaSamples shadowSamples
     * adaptive]}, by default 800 500 1 1 false. Anti-aliasing is a GRID over the pixel; shadow samples above 1 make
     * every lamp a disk of radius 10; {@code adaptive} refines both only where samples disagree.
     *
     * @param args optionally {@code width height aaSamples shadowSamples adaptive}
     */
    public static void main(String[] args) {
        int width = args.length > 0 ? Integer.parseInt(args[0]) : 800;
        int height = args.length > 1 ? Integer.parseInt(args[1]) : 500;
        int aa = args.length > 2 ? Integer.parseInt(args[2]) : 1;
        int shadows = args.length > 3 ? Integer.parseInt(args[3]) : 1;
        boolean adaptive = args.length > 4 && Boolean.parseBoolean(args[4]);
        StreetScene street = new StreetScene(shadows > 1 ? StreetOptions.soft(10, shadows) : StreetOptions.HARD);
        SamplingConfig sampling = new SamplingConfig(aa, TargetShape.RECTANGLE, SamplingPattern.GRID);
        Camera camera = street.camera(width, height)
                .setSamplingConfig(adaptive && aa > 1 ? sampling.adaptive(ADAPTIVE_THRESHOLD) : sampling)
                .setRenderSettings(RenderSettings.DEFAULT.withShadowSampling(SamplingPattern.JITTERED, adaptive))
                .build();
        camera.renderImage();
        System.out.println(street.primitiveCount() + " primitives; wrote " + camera.writeToImage("street-render"));
        System.out.print(camera.getLastStatistics().format());
    }

    /**
     * The scene (build a new StreetScene for an independent copy).
     *
     * @return the scene, shared: changing it changes this street
     */
    public Scene scene() {
        return scene;
    }

    /**
     * The lamp settings the street was built with.
     *
     * @return the options given to the constructor
     */
    public StreetOptions options() {
        return options;
    }

    /**
     * The view down the street at the given resolution; the view plane takes the image's aspect ratio.
     *
     * @param width image width in pixels
     * @param height image height in pixels
     * @return a camera builder with location, direction, view plane, resolution and ray tracer set
     */
    public Camera.Builder camera(int width, int height) {
        return Camera.getBuilder()
                .setLocation(CAMERA_LOCATION)
                .setDirection(CAMERA_TARGET, Vector.AXIS_Z)
                .setVpDistance(VP_DISTANCE)
                .setVpSize(VP_WIDTH, VP_WIDTH * height / width)
                .setResolution(width, height)
                .setRayTracer(scene, RayTracerType.SIMPLE);
    }

    /**
     * The glowing glass globes of the street lamps, each with its centre.
     *
     * @return an unmodifiable list of the lamp globes
     */
    public List<Landmark> lampGlobes() {
        return Collections.unmodifiableList(lampGlobes);
    }

    /**
     * The lit windows, shop windows and the advert (emissive polygons), each with the centre of a pane clear of the
     * glazing bars.
     *
     * @return an unmodifiable list of the lit windows
     */
    public List<Landmark> litWindows() {
        return Collections.unmodifiableList(litWindows);
    }

    /**
     * The moon: an emissive sphere far away, above the end of the street.
     *
     * @return the moon sphere
     */
    public Sphere moon() {
        return moon;
    }

    /**
     * Primitives the renderer works with: triangles of meshes and polygon fans counted one by one, plus spheres,
     * cylinders and planes; an instance's primitives count once per instance.
     *
     * @return the number of primitives
     */
    public int primitiveCount() {
        Accelerator flat = Accelerator.build(scene.geometries, false);
        return (int) flat.placedPrimitiveCount() + flat.unboundedPrimitiveCount();
    }

    // ------------------------------------------------------------------ ground

    private void addGround() {
        Double3 asphalt = new Double3(0.24, 0.24, 0.26);
        // Wet asphalt: dark, with a broad sheen and a faint mirror image of the lights.
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Z)
                .setMaterial(new Material()
                        .setKd(asphalt)
                        .setKa(asphalt)
                        .setKs(0.35)
                        .setShininess(30)
                        .setKr(0.14)));
        Material paint = matte(new Double3(0.62, 0.62, 0.58));
        // Dashed centre line and the zebra crossing in the foreground (a hair above the asphalt).
        for (double y = STREET_START; y < STREET_END; y += 120) {
            scene.geometries.add(rectangleZ(-1.5, y, 1.5, y + 60, 0.05).setMaterial(paint));
        }
        for (double x = -126; x < ROAD - 10; x += 24) {
            scene.geometries.add(rectangleZ(x, -90, x + 12, -20, 0.05).setMaterial(paint));
        }
        Material kerb = matte(new Double3(0.42, 0.41, 0.40));
        Material pavement = matte(new Double3(0.30, 0.29, 0.28));
        // Sidewalks and kerbs in segments, so no long thin triangle spans the whole BVH.
        for (double y = STREET_START; y < STREET_END; y += 400) {
            double y1 = Math.min(y + 400, STREET_END);
            for (int side = -1; side <= 1; side += 2) {
                MeshBuilder kerbStones = new MeshBuilder(), slab = new MeshBuilder();
                boxX(kerbStones, side, ROAD, KERB, y, y1, 0, SIDEWALK_TOP + 0.4);
                boxX(slab, side, KERB, FACADE, y, y1, 0, SIDEWALK_TOP);
                scene.geometries.add(
                        kerbStones.build().setMaterial(kerb), slab.build().setMaterial(pavement));
            }
        }
    }

    // ------------------------------------------------------------------ houses

    private static final Double3[] WALLS = {
        new Double3(0.38, 0.16, 0.11), // brick
        new Double3(0.42, 0.32, 0.18), // ochre
        new Double3(0.33, 0.32, 0.30), // stone
        new Double3(0.42, 0.38, 0.32), // cream
        new Double3(0.22, 0.25, 0.30), // slate blue
        new Double3(0.28, 0.35, 0.28), // sage
    };

    private static final Color[] LAMPLIGHT = {
        new Color(255, 196, 110), new Color(240, 170, 85), new Color(255, 220, 160), new Color(225, 150, 70),
    };

    private static final Color[] SHOP_LIGHT = {
        new Color(255, 236, 190), new Color(215, 230, 255), new Color(255, 214, 150),
    };

    private static final Color[] NEON = {
        new Color(255, 60, 90), new Color(50, 215, 255), new Color(110, 255, 120), new Color(255, 170, 40),
    };

    private static final Double3[] AWNINGS = {
        new Double3(0.45, 0.06, 0.06),
        new Double3(0.06, 0.28, 0.12),
        new Double3(0.08, 0.12, 0.40),
        new Double3(0.40, 0.30, 0.05),
    };

    /** One row of houses along the street; {@code side} +1 is the right (+x) side, -1 the left. */
    private void addHouses(int side) {
        Facade facade = new Facade(new Point(side * FACADE, 0, 0), 1, 1, -side);
        double y = STREET_START + 100 + random.nextInt(120);
        while (y < STREET_END - 300) {
            double width = 220 + random.nextInt(200);
            addHouse(facade, y, y + width, 260 + random.nextInt(240));
            y += width + (random.nextInt(4) == 0 ? 40 + random.nextInt(40) : 0);
        }
    }

    /** Houses across the far end of the street, facing the camera: they close the view below the moon. */
    private void addEndOfStreet() {
        Facade facade = new Facade(new Point(0, STREET_END + 150, 0), 0, 1, -1);
        double u = -FACADE - 350;
        while (u < FACADE + 350) {
            double width = 200 + random.nextInt(160);
            addHouse(facade, u, u + width, 240 + random.nextInt(160));
            u += width;
        }
    }

    /** A house: its front from u0 to u1 on the facade, side walls going back, a cornice, shop and windows. */
    private void addHouse(Facade f, double u0, double u1, double height) {
        Double3 wall = WALLS[random.nextInt(WALLS.length)];
        Material walls = matte(wall);
        double depth = 400;
        scene.geometries.add(
                f.rectangle(u0, u1, 0, height, 0).setMaterial(walls),
                new Polygon(f.at(u0, 0, 0), f.at(u0, height, 0), f.at(u0, height, -depth), f.at(u0, 0, -depth))
                        .setMaterial(walls),
                new Polygon(f.at(u1, 0, 0), f.at(u1, 0, -depth), f.at(u1, height, -depth), f.at(u1, height, 0))
                        .setMaterial(walls));
        MeshBuilder ledge = new MeshBuilder();
        f.box(ledge, u0 - 2, u1 + 2, height - 10, height, -1, 7);
        scene.geometries.add(ledge.build().setMaterial(matte(wall.scale(1.2))));

        if (random.nextInt(5) < 2) {
            addShop(f, u0, u1);
        } else {
            double door = (u0 + u1) / 2;
            scene.geometries.add(f.rectangle(door - 14, door + 14, SIDEWALK_TOP, 60, 0.4)
                    .setMaterial(matte(new Double3(0.18, 0.10, 0.06))));
            for (double w : new double[] {(u0 + door) / 2 - 5, (door + u1) / 2 + 5}) {
                if (w - 13 > u0 + 8 && w + 13 < u1 - 8) addWindow(f, w, 22, 64);
            }
        }
        int columns = (int) ((u1 - u0 - 30) / 58);
        double margin = (u1 - u0 - columns * 58) / 2;
        for (double floor = 95; floor + 60 < height - 10; floor += 72) {
            for (int c = 0; c < columns; c++) addWindow(f, u0 + margin + 29 + 58 * c, floor + 14, floor + 56);
        }
    }

    /** A shop on the ground floor: lit display windows between pillars, a door, an awning and a neon sign. */
    private void addShop(Facade f, double u0, double u1) {
        Color light = SHOP_LIGHT[random.nextInt(SHOP_LIGHT.length)].scale(0.5 + 0.2 * random.nextDouble());
        double doorEnd = u1 - 14, doorStart = doorEnd - 28;
        scene.geometries.add(f.rectangle(doorStart, doorEnd, SIDEWALK_TOP, 62, 0.4)
                .setEmission(light.scale(0.6))
                .setMaterial(new Material().setKa(0)));
        double start = u0 + 14, end = doorStart - 8;
        int panes = Math.max(1, (int) Math.round((end - start) / 62));
        double pane = (end - start - 6 * (panes - 1)) / panes;
        for (int i = 0; i < panes; i++) {
            double a = start + i * (pane + 6);
            Geometry window =
                    f.rectangle(a, a + pane, 14, 62, 0.4).setEmission(light).setMaterial(new Material().setKa(0));
            scene.geometries.add(window);
            litWindows.add(new Landmark(window, f.at(a + pane / 2, 38, 0.4)));
        }
        Double3 cloth = AWNINGS[random.nextInt(AWNINGS.length)];
        scene.geometries.add(
                new Polygon(f.at(u0 + 8, 74, 0.5), f.at(u0 + 8, 64, 22), f.at(u1 - 8, 64, 22), f.at(u1 - 8, 74, 0.5))
                        .setMaterial(matte(cloth)));
        // The sign: a dark board with glowing letters.
        double boardStart = u0 + 24, boardEnd = u1 - 24;
        scene.geometries.add(f.rectangle(boardStart, boardEnd, 78, 94, 0.4).setMaterial(matte(new Double3(0.05))));
        Color neon = NEON[random.nextInt(NEON.length)];
        double letters = Math.min(10, Math.floor((boardEnd - boardStart - 16) / 11));
        double u = (boardStart + boardEnd) / 2 - letters * 11 / 2 + 2;
        for (int i = 0; i < letters; i++, u += 11) {
            scene.geometries.add(f.rectangle(u, u + 5 + random.nextInt(3), 81, 91, 0.7)
                    .setEmission(neon)
                    .setMaterial(new Material().setKa(0)));
        }
    }

    /** A window centred at u from v0 to v1: lit (warm or television blue) with glazing bars, or dark glass. */
    private void addWindow(Facade f, double u, double v0, double v1) {
        double u0 = u - 13, u1 = u + 13;
        if (random.nextInt(100) < 42) {
            Color light = random.nextInt(12) == 0
                    ? new Color(110, 140, 215) // a television
                    : LAMPLIGHT[random.nextInt(LAMPLIGHT.length)];
            Geometry pane = f.rectangle(u0, u1, v0, v1, 0.4)
                    .setEmission(light.scale(0.55 + 0.4 * random.nextDouble()))
                    .setMaterial(new Material().setKa(0));
            scene.geometries.add(pane);
            // The lower left pane: between the left frame, the vertical bar and the transom.
            litWindows.add(new Landmark(pane, f.at(u - 7, (v0 + v1) / 2 - 6, 0.4)));
            Material frame = matte(new Double3(0.12, 0.11, 0.10));
            double mid = (v0 + v1) / 2 + 4;
            scene.geometries.add(
                    f.rectangle(u - 1, u + 1, v0, v1, 0.7).setMaterial(frame),
                    f.rectangle(u0, u1, mid - 1, mid + 1, 0.7).setMaterial(frame));
        } else {
            // Dark glass: mirrors the street lamps.
            scene.geometries.add(f.rectangle(u0, u1, v0, v1, 0.4)
                    .setMaterial(new Material()
                            .setKd(0.03)
                            .setKa(0.06)
                            .setKs(0.8)
                            .setShininess(250)
                            .setKr(0.3)));
        }
    }

    // ------------------------------------------------------------------ lamps, trees, shelter, moon

    /**
     * The ten lamp posts are one prototype placed ten times (instancing: the scene stores the post once), modelled
     * standing at the origin of x and y, on the sidewalk. The glass globes stay plain spheres of the scene: each
     * holds its lamp's light, so every shadow ray toward a lamp starts inside its globe, and a globe inside the
     * instance would send all of them through the instance (27% more primitive tests per ray, measured; docs/BENCHMARKS.md).
     */
    private void addLamps() {
        Material iron = new Material().setKd(0.07).setKa(0.1).setKs(0.6).setShininess(80);
        Material glass = new Material().setKa(0).setKt(GLOBE_KT);
        // A point that sees the light at elevation e sees the far lower rim of its disk (radius 10) pass above the
        // neck while 10 / cos e + tan e stays below the gap from the light down to the neck's top (18 here): up to
        // e = 52 degrees, beyond about 110 from the post. Nearer, the neck hides part of the disk, a faint penumbra
        // that lies where the post's own shadow does anyway. A globe sitting lower on its neck spreads that
        // penumbra over the whole street, where adaptive shadows then fire every sample.
        double neck = GLOBE_CENTRE - GLOBE_RADIUS;
        Point foot = new Point(0, 0, SIDEWALK_TOP);
        Prototype post = new Prototype(
                "lamp-post",
                new Geometries(
                        new Cylinder(4.5, new Ray(foot, Vector.AXIS_Z), 14).setMaterial(iron),
                        new Cylinder(2.2, new Ray(foot, Vector.AXIS_Z), neck - 5 - SIDEWALK_TOP).setMaterial(iron),
                        new Cylinder(1, new Ray(new Point(0, 0, neck - 5), Vector.AXIS_Z), 5.5).setMaterial(iron)));
        for (int k = 0; k < 5; k++) {
            for (int side = -1; side <= 1; side += 2) {
                double x = side * 153, y = (side < 0 ? -100 : 180) + 560 * k;
                scene.geometries.add(new Instance(post, Transform.translate(x, y, 0)));
                Sphere globe = new Sphere(new Point(x, y, GLOBE_CENTRE), GLOBE_RADIUS);
                globe.setEmission(new Color(140, 118, 80)).setMaterial(glass);
                scene.geometries.add(globe);
                lampGlobes.add(new Landmark(globe, globe.getCenter()));
                scene.lights.add(new PointLight(new Color(1080, 790, 490), new Point(x, y, LAMP_HEIGHT))
                        .setKq(1.2e-4)
                        .setRadius(options.lampRadius())
                        .setNumSamples(options.lampSamples()));
            }
        }
    }

    private void addTrees() {
        Material bark = matte(new Double3(0.20, 0.13, 0.08));
        Double3 leaves = new Double3(0.16, 0.32, 0.12);
        Material foliage =
                new Material().setKd(leaves).setKa(leaves).setKs(0.08).setShininess(8);
        List<Point> trunks = new ArrayList<>();
        for (int k = 0; k < 5; k++) trunks.add(new Point(-212, 180 + 560 * k, SIDEWALK_TOP));
        for (int k = 1; k < 5; k++) trunks.add(new Point(212, 460 + 560 * k, SIDEWALK_TOP));
        for (Point t : trunks) {
            scene.geometries.add(new Cylinder(5, new Ray(t, Vector.AXIS_Z), 150).setMaterial(bark));
            scene.geometries.add(new Sphere(new Point(t.x, t.y, 185), 32).setMaterial(foliage));
            // Clumps of leaves on a shell around the crown, spread evenly by the golden angle.
            for (int i = 0; i < 14; i++) {
                double h = 1 - 1.6 * (i + 0.5) / 14, ring = Math.sqrt(1 - h * h);
                double a = 2.39996 * i + random.nextDouble() * 0.4;
                double r = 30 + 6 * random.nextDouble();
                Point c = new Point(t.x + r * ring * Math.cos(a), t.y + r * ring * Math.sin(a), 185 + 0.8 * r * h);
                scene.geometries.add(new Sphere(c, 15 + 7 * random.nextDouble()).setMaterial(foliage));
            }
        }
    }

    /** A bus shelter on the right sidewalk: steel posts, a glass roof and back, a lit advert, a bench and a spot. */
    private void addShelter(Point corner) {
        double x0 = corner.x, x1 = x0 + 50, y0 = corner.y, y1 = y0 + 140, z = corner.z;
        Material steel = new Material().setKd(0.25).setKa(0.2).setKs(0.7).setShininess(120);
        for (double px : new double[] {x0, x1}) {
            for (double py : new double[] {y0, y1}) {
                scene.geometries.add(
                        new Cylinder(1.5, new Ray(new Point(px, py, z), Vector.AXIS_Z), 58).setMaterial(steel));
            }
        }
        // The roof slopes down toward the road; a thin pane, so an index of 1 (its two refractions cancel).
        Material roofGlass = new Material()
                .setKd(new Double3(0.05, 0.07, 0.08))
                .setKa(0.05)
                .setKs(0.6)
                .setShininess(200)
                .setKt(new Double3(0.55, 0.68, 0.72));
        scene.geometries.add(new Polygon(
                        new Point(x0 - 5, y0 - 5, z + 57),
                        new Point(x1 + 5, y0 - 5, z + 61),
                        new Point(x1 + 5, y1 + 5, z + 61),
                        new Point(x0 - 5, y1 + 5, z + 57))
                .setMaterial(roofGlass));
        MeshBuilder frame = new MeshBuilder();
        frame.box(x0 - 6, y0 - 6, z + 55, x0 - 3, y1 + 6, z + 57);
        frame.box(x1 + 3, y0 - 6, z + 59, x1 + 6, y1 + 6, z + 61);
        scene.geometries.add(frame.build().setMaterial(steel));
        scene.geometries.add(new Polygon(
                        new Point(x1 - 2, y0 + 2, z + 6),
                        new Point(x1 - 2, y1 - 2, z + 6),
                        new Point(x1 - 2, y1 - 2, z + 54),
                        new Point(x1 - 2, y0 + 2, z + 54))
                .setMaterial(new Material()
                        .setKd(0.03)
                        .setKa(0.03)
                        .setKs(0.5)
                        .setShininess(200)
                        .setKt(new Double3(0.7, 0.8, 0.82))));
        // The advert at the far end faces the camera: a glowing panel with a bright picture on it.
        Geometry advert = new Polygon(
                        new Point(x0 + 3, y1, z + 8),
                        new Point(x1 - 3, y1, z + 8),
                        new Point(x1 - 3, y1, z + 54),
                        new Point(x0 + 3, y1, z + 54))
                .setEmission(new Color(60, 110, 170))
                .setMaterial(new Material().setKa(0));
        Geometry picture = new Polygon(
                        new Point(x0 + 8, y1 - 0.3, z + 24),
                        new Point(x1 - 8, y1 - 0.3, z + 24),
                        new Point(x1 - 8, y1 - 0.3, z + 48),
                        new Point(x0 + 8, y1 - 0.3, z + 48))
                .setEmission(new Color(235, 175, 70))
                .setMaterial(new Material().setKa(0));
        scene.geometries.add(advert, picture);
        litWindows.add(new Landmark(advert, new Point((x0 + x1) / 2, y1, z + 16)));
        scene.geometries.add(BenchModel.build(new Point(x1 - 16, (y0 + y1) / 2, z), -1));
        // The spot hangs low enough that its disk (radius 10) stays under the glass roof, which would otherwise
        // dim part of it for every point of the street.
        scene.lights.add(new SpotLight(
                        new Color(700, 680, 640), new Point((x0 + x1) / 2, (y0 + y1) / 2, z + 42), new Vector(0, 0, -1))
                .setNarrowBeam(6)
                .setKq(6e-4)
                .setRadius(options.lampRadius())
                .setNumSamples(options.lampSamples()));
    }

    /**
     * Puddles on the asphalt: flat mirrors a hair above it, where the camera sees the reflections of the moon and
     * of lamps in the road (where the line from the camera to each mirror image crosses the road).
     */
    private void addPuddles() {
        Material water = new Material()
                .setKd(0.14)
                .setKa(0.14)
                .setKs(0.8)
                .setShininess(300)
                .setKr(0.5);
        // Long along the street: seen from the camera the road is foreshortened about fivefold.
        double[][] puddles = {{10, -18, 36, 44}, {-74, -88, 24, 24}, {-74, 118, 22, 34}};
        for (double[] p : puddles) {
            // An irregular octagon: an ellipse with each corner pulled in by up to 8%, little enough that the
            // outline stays convex (a corner would have to come in by about 29% to dent it).
            Point[] outline = new Point[8];
            for (int i = 0; i < 8; i++) {
                double a = 2 * Math.PI * i / 8, wobble = 0.92 + 0.08 * random.nextDouble();
                outline[i] = new Point(p[0] + p[2] * Math.cos(a) * wobble, p[1] + p[3] * Math.sin(a) * wobble, 0.08);
            }
            scene.geometries.add(new Polygon(outline).setMaterial(water));
        }
    }

    private void addMoon() {
        Vector toMoon = direction(5, 12);
        moon = new Sphere(CAMERA_LOCATION.add(toMoon.scale(MOON_DISTANCE)), MOON_RADIUS);
        moon.setEmission(new Color(242, 236, 212)).setMaterial(new Material().setKa(0));
        scene.geometries.add(moon);
        // Maria: greyer spheres bulging a little out of the face turned to the camera, each showing a disk of the
        // given radius at (right, up) fractions of the moon's radius, clear of the moon's centre by a quarter of its
        // radius and inside its outline.
        Vector right = toMoon.crossProduct(Vector.AXIS_Z).normalize(), up = right.crossProduct(toMoon);
        double[][] maria = {{-0.42, 0.32, 0.24}, {0.3, 0.4, 0.22}, {0.18, -0.5, 0.22}, {-0.42, -0.25, 0.16}};
        for (double[] m : maria) {
            double depth = Math.sqrt(1 - m[0] * m[0] - m[1] * m[1]);
            Vector out = right.scale(m[0]).add(up.scale(m[1])).add(toMoon.scale(-depth));
            double radius = m[2] * MOON_RADIUS / 0.6; // shows a disk of m[2] moon radii: it bulges out 0.2 of itself
            Point centre = moon.getCenter().add(out.scale(MOON_RADIUS - 0.8 * radius));
            scene.geometries.add(new Sphere(centre, radius)
                    .setEmission(new Color(204, 201, 188))
                    .setMaterial(new Material().setKa(0)));
        }
        // The moonlight falls from a little higher than the (enlarged) disk is drawn: shadow rays toward the light
        // then pass beside the moon sphere instead of all ending on it.
        scene.lights.add(
                new DirectionalLight(new Color(44, 54, 84), direction(5, 21).scale(-1)));
        addStars();
    }

    /** A few stars: tiny far spheres in the sky above the houses, none near the moon. */
    private void addStars() {
        for (int i = 0; i < 60; i++) {
            double azimuth = -32 + 64 * random.nextDouble(), elevation = 6 + 22 * random.nextDouble();
            if (Math.hypot(azimuth - 5, elevation - 12) < 5) continue;
            Vector d = direction(azimuth, elevation);
            double brightness = 120 + 135 * random.nextDouble();
            Color colour = random.nextInt(3) == 0
                    ? new Color(0.8 * brightness, 0.88 * brightness, brightness)
                    : new Color(brightness, brightness, 0.92 * brightness);
            scene.geometries.add(new Sphere(CAMERA_LOCATION.add(d.scale(50_000)), 30 + 25 * random.nextDouble())
                    .setEmission(colour)
                    .setMaterial(new Material().setKa(0)));
        }
    }

    /** The unit vector at the given azimuth (degrees from +y toward +x) and elevation (degrees above the ground). */
    private static Vector direction(double azimuth, double elevation) {
        double a = Math.toRadians(azimuth), e = Math.toRadians(elevation);
        return new Vector(Math.cos(e) * Math.sin(a), Math.cos(e) * Math.cos(a), Math.sin(e));
    }

    // ------------------------------------------------------------------ helpers

    private static Material matte(Double3 colour) {
        return new Material().setKd(colour).setKa(colour).setKs(0.05).setShininess(10);
    }

    /** A horizontal rectangle at height z. */
    private static Geometry rectangleZ(double x0, double y0, double x1, double y1, double z) {
        return new Polygon(new Point(x0, y0, z), new Point(x1, y0, z), new Point(x1, y1, z), new Point(x0, y1, z));
    }

    /** A box from {@code side * a} to {@code side * b} in x (a and b measured outward from the street's axis). */
    private static void boxX(
            MeshBuilder mesh, int side, double a, double b, double y0, double y1, double z0, double z1) {
        mesh.box(Math.min(side * a, side * b), y0, z0, Math.max(side * a, side * b), y1, z1);
    }
}
