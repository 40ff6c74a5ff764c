package sceneio;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import primitives.Printable;

/**
 * Where the files a scene refers to (OBJ meshes, their MTL files, textures) may be: inside the scene file's
 * folder tree, or a folder tree the user allowed ({@code --allow-path}, {@link SceneLoader#load(Path, List)}), after
 * following symbolic links. A scene file from a stranger must not read the machine's other files.
 *
 * <p>A reference is resolved one name at a time, links followed as the operating system follows them, and refused
 * as soon as it leaves the allowed trees, before the path outside is looked at: nothing outside is ever read,
 * listed or tested for existence, so the messages cannot tell a stranger which files exist elsewhere (as "not
 * found" against "outside" would). The folders are assumed not to change while the scene loads.
 */
final class FileConfinement {
    /** Most links followed in one reference, as Linux allows (beyond it a loop is likely). */
    static final int MAX_LINKS = 40;

    /** The allowed folders with links followed; the first is the scene file's. */
    private final List<Path> roots;

    /**
     * @param sceneFolder the scene file's folder, where references start
     * @param alsoAllowed further folders whose trees references may lead into
     */
    FileConfinement(Path sceneFolder, List<Path> alsoAllowed) {
        List<Path> all = new ArrayList<>();
        all.add(real(sceneFolder));
        for (Path folder : alsoAllowed) all.add(real(folder));
        roots = List.copyOf(all);
    }

    /** The folder with links followed, or as given (absolute, normalized) when it cannot be resolved. */
    private static Path real(Path folder) {
        try {
            return folder.toRealPath();
        } catch (IOException | SecurityException e) {
            return folder.toAbsolutePath().normalize();
        }
    }

    /**
     * The file a relative reference names, with every link followed, inside an allowed tree. It need not exist:
     * the caller reports a missing file (inside, so saying so reveals nothing).
     *
     * @param kind what the file is, for messages ("OBJ file")
     * @throws IllegalArgumentException naming the reference and why it is refused
     */
    Path resolve(String kind, String reference) {
        String quoted = kind + " \"" + Printable.of(reference) + "\"";
        Path relative;
        try {
            relative = Path.of(reference);
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException(quoted + " is not a valid path: " + e.getReason());
        }
        if (reference.isBlank() || relative.isAbsolute() || relative.getRoot() != null) {
            throw new IllegalArgumentException(
                    "the " + kind + " must be a path relative to the scene file's folder, but was \""
                            + Printable.of(reference) + "\"");
        }
        Path current = roots.get(0);
        Deque<Path> pending = new ArrayDeque<>();
        for (Path name : relative) pending.addLast(name);
        int links = 0;
        while (!pending.isEmpty()) {
            String name = pending.removeFirst().toString();
            if (name.isEmpty() || name.equals(".")) continue;
            if (name.equals("..")) {
                // current has no links in it, so its lexical parent is its real parent.
                if (current.getParent() != null) current = current.getParent();
                continue;
            }
            Path next = current.resolve(name);
            if (!mayLookAt(next)) throw outside(quoted, next);
            if (!Files.isSymbolicLink(next)) {
                current = next;
                continue;
            }
            if (++links > MAX_LINKS) {
                throw new IllegalArgumentException(quoted + " follows more than " + MAX_LINKS + " symbolic links");
            }
            Path target;
            try {
                target = Files.readSymbolicLink(next);
            } catch (IOException | SecurityException e) {
                throw new IllegalArgumentException(
                        quoted + ": the link " + Printable.of(next.toString()) + " cannot be read");
            }
            if (target.getRoot() != null) current = target.getRoot();
            List<Path> names = new ArrayList<>();
            for (Path part : target) names.add(part);
            for (int i = names.size() - 1; i >= 0; i--) pending.addFirst(names.get(i));
        }
        if (!inside(current)) throw outside(quoted, current);
        return current;
    }

    /** Inside an allowed tree, or a folder on the way to one (the root, /home...): nothing else is looked at. */
    private boolean mayLookAt(Path path) {
        for (Path root : roots) {
            if (path.startsWith(root) || root.startsWith(path)) return true;
        }
        return false;
    }

    private boolean inside(Path path) {
        for (Path root : roots) {
            if (path.startsWith(root)) return true;
        }
        return false;
    }

    private IllegalArgumentException outside(String quoted, Path at) {
        return new IllegalArgumentException(quoted + " leads outside the scene file's folder "
                + Printable.message(roots.get(0).toString()) + " (to " + Printable.of(at.toString())
                + ", links followed); referenced files must lie in that folder tree or one allowed with --allow-path"
                + " DIR (SceneLoader.load(file, allowedFolders) in Java)");
    }
}
