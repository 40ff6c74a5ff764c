package architecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * What a project depending on this library gets: every dependency of the default build is either test-scoped or
 * optional, so Maven resolves none of them for a consumer (the consumer check, {@code mvn -Pconsumer-check
 * verify}, proves it end to end); and the jar names its module.
 */
class LibraryDependenciesTest {
    @Test
    void everyRuntimeDependencyIsOptional() throws Exception {
        Document pom = DocumentBuilderFactory.newInstance()
                .newDocumentBuilder()
                .parse(Path.of("pom.xml").toFile());
        Element project = pom.getDocumentElement();
        List<String> leaking = new ArrayList<>();
        int checked = 0;
        for (Element dependencies : children(project, "dependencies")) {
            for (Element dependency : children(dependencies, "dependency")) {
                checked++;
                String scope = text(dependency, "scope"), optional = text(dependency, "optional");
                if (!"test".equals(scope) && !"true".equals(optional)) leaking.add(text(dependency, "artifactId"));
            }
        }
        assertTrue(checked >= 6, "the default build's dependencies were found: " + checked);
        assertEquals(List.of(), leaking, "dependencies a consumer would get; mark them <optional>true</optional>");
    }

    @Test
    void theJarNamesItsModule() throws Exception {
        Document pom = DocumentBuilderFactory.newInstance()
                .newDocumentBuilder()
                .parse(Path.of("pom.xml").toFile());
        String name = pom.getElementsByTagName("Automatic-Module-Name").item(0).getTextContent();
        assertFalse(name.isBlank());
        assertTrue(name.matches("[a-z][a-z0-9]*(\\.[a-z][a-z0-9]*)*"), name);
    }

    private static List<Element> children(Element parent, String tag) {
        List<Element> list = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(tag)) list.add(e);
        }
        return list;
    }

    private static String text(Element parent, String tag) {
        List<Element> found = children(parent, tag);
        return found.isEmpty() ? null : found.get(0).getTextContent().trim();
    }
}
