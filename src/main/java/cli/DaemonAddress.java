package cli;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;
import launch.JavaLaunch;

/**
 * Where the render daemon that can serve this program listens: one daemon per JDK, class path (and the newest
 * file on it, so a rebuilt program never talks to a daemon running the old code) and working folder (the command's
 * relative paths are the daemon's). Its socket, lock and log live in a folder that only the
 * user can open, {@code <java.io.tmpdir>/raytracer-daemon-<user>}, so no other user can send it commands.
 *
 * @param socket the daemon's Unix domain socket
 * @param lock the file the live daemon holds locked, so at most one serves the socket
 * @param log where the daemon's own output goes (its start and its failures)
 */
record DaemonAddress(Path socket, Path lock, Path log) {
    /** The longest socket path every Unix takes (Linux allows 107 bytes, macOS 103). */
    static final int MAX_SOCKET_PATH_BYTES = 100;

    private static final Set<PosixFilePermission> PRIVATE = PosixFilePermissions.fromString("rwx------");

    /**
     * The address for a daemon running this program with {@code launch} in {@code workingFolder}.
     *
     * @throws BadInputException if the folder cannot be made private to the user, or the file system has no POSIX
     *     permissions
     */
    static DaemonAddress of(JavaLaunch launch, Path workingFolder) throws BadInputException, IOException {
        return in(Path.of(System.getProperty("java.io.tmpdir")), launch, workingFolder);
    }

    /** As {@link #of}, with {@code tmp} for {@code java.io.tmpdir}. */
    static DaemonAddress in(Path tmp, JavaLaunch launch, Path workingFolder) throws BadInputException, IOException {
        Path folder = tmp.resolve("raytracer-daemon-" + userTag());
        makePrivate(folder);
        String key = key(launch, workingFolder);
        Path socket = folder.resolve(key + ".sock");
        int length = socket.toString().getBytes(StandardCharsets.UTF_8).length;
        if (length > MAX_SOCKET_PATH_BYTES) {
            throw new BadInputException("--daemon: the socket path " + socket + " is " + length
                    + " bytes, more than the "
                    + MAX_SOCKET_PATH_BYTES + " a Unix domain socket's path may have everywhere; give the JVM a shorter"
                    + " -Djava.io.tmpdir");
        }
        return at(socket);
    }

    /** The address of a daemon whose socket is {@code socket} (its lock and log beside it). */
    static DaemonAddress at(Path socket) {
        String name = socket.getFileName().toString().replaceFirst("\\.sock$", "");
        return new DaemonAddress(socket, socket.resolveSibling(name + ".lock"), socket.resolveSibling(name + ".log"));
    }

    private static String userTag() {
        return System.getProperty("user.name", "user").replaceAll("[^A-Za-z0-9_.-]", "_");
    }

    /** Creates {@code folder} readable by the user only, or checks that an existing one is. */
    static void makePrivate(Path folder) throws BadInputException, IOException {
        if (!FileSystems.getDefault().supportedFileAttributeViews().contains("posix")) {
            throw new BadInputException("--daemon needs a file system with POSIX permissions (Linux, macOS)");
        }
        if (!Files.exists(folder)) {
            try {
                Files.createDirectory(folder, PosixFilePermissions.asFileAttribute(PRIVATE));
            } catch (FileAlreadyExistsException raced) {
                // another client created it: checked below like any existing folder
            } catch (NoSuchFileException e) {
                throw new BadInputException("--daemon: cannot create " + folder + ", as its folder does not exist;"
                        + " give the JVM an existing -Djava.io.tmpdir");
            }
        }
        PosixFileAttributes attributes = Files.getFileAttributeView(
                        folder, PosixFileAttributeView.class, LinkOption.NOFOLLOW_LINKS)
                .readAttributes();
        String me = System.getProperty("user.name");
        if (!attributes.isDirectory()
                || !attributes.owner().getName().equals(me)
                || !attributes.permissions().equals(PRIVATE)) {
            throw new BadInputException("--daemon: " + folder + " must be a folder owned by " + me
                    + " with permissions rwx------, but is " + (attributes.isDirectory() ? "a folder" : "not a folder")
                    + " owned by " + attributes.owner().getName() + " with "
                    + PosixFilePermissions.toString(attributes.permissions())
                    + "; remove it, or give the JVM another -Djava.io.tmpdir");
        }
    }

    /**
     * A 64-bit FNV-1a hash of what makes daemons interchangeable. It only keeps daemons apart (the folder's
     * permissions keep other users out), so it need not be cryptographic; MessageDigest would cost the client's
     * start about 20 ms.
     */
    private static String key(JavaLaunch launch, Path workingFolder) {
        String identity = String.join(
                "\n",
                launch.java(),
                launch.classPath(),
                workingFolder.toAbsolutePath().normalize().toString(),
                Long.toString(newestFile(launch.classPath())));
        long hash = 0xcbf29ce484222325L;
        for (byte b : identity.getBytes(StandardCharsets.UTF_8)) {
            hash = (hash ^ (b & 0xff)) * 0x100000001b3L;
        }
        return Long.toHexString(hash); // (String.format would cost the client's start about 7 ms)
    }

    /** The newest modification time (ms) of any file on the class path, so a rebuild gives a new daemon. */
    static long newestFile(String classPath) {
        long newest = 0;
        for (String entry : classPath.split(File.pathSeparator)) {
            if (!entry.isEmpty()) newest = Math.max(newest, newestFile(new File(entry)));
        }
        return newest;
    }

    /** java.io's listing, which starts faster than the stream of Files.walk (no lambdas, fewer classes). */
    private static long newestFile(File file) {
        long newest = file.lastModified();
        File[] children = file.isDirectory() ? file.listFiles() : null;
        if (children != null) {
            for (File child : children) newest = Math.max(newest, newestFile(child));
        }
        return newest;
    }
}
