"""Every server-manager XML of the plugin against a freshly constructed filter: each property's
default is the filter's own, and each range domain is the range the filter clamps to, so that the
GUI and the C++/Python defaults cannot drift apart.
"""
import glob
import math
import os
import unittest
import xml.etree.ElementTree as ElementTree

XML_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "paraview_plugin", "xml")
NUMERIC = {"IntVectorProperty": int, "DoubleVectorProperty": float}


def properties():
    """(xml file, class, property element) for every numeric single-value property with a setter."""
    for path in sorted(glob.glob(os.path.join(XML_DIR, "*.xml"))):
        for proxy in ElementTree.parse(path).getroot().iter():
            if "class" not in proxy.attrib:
                continue
            for prop in proxy:
                if prop.tag in NUMERIC and prop.get("number_of_elements") == "1" and prop.get("command") \
                        and prop.get("default_values") is not None and prop.get("information_only") != "1":
                    yield os.path.basename(path), proxy.get("class"), prop


class PluginXml(unittest.TestCase):
    def test_defaults_and_ranges_match_the_filters(self):
        import clothtrack

        checked = 0
        for path, class_name, prop in properties():
            cast = NUMERIC[prop.tag]
            setter = prop.get("command")
            getter = "Get" + setter[3:]
            checked += 1
            with self.subTest(xml=path, property=prop.get("name")):
                algorithm = getattr(clothtrack, class_name)()
                self.assertTrue(hasattr(algorithm, getter), "%s has no %s" % (class_name, getter))
                default = cast(prop.get("default_values"))
                actual = getattr(algorithm, getter)()
                self.assertTrue(math.isclose(actual, default, rel_tol=1e-12, abs_tol=1e-12),
                                "%s.%s: XML default %s, filter %s" % (class_name, prop.get("name"), default, actual))
                for domain in prop.findall("IntRangeDomain") + prop.findall("DoubleRangeDomain"):
                    for bound, beyond in (("min", -1), ("max", +1)):
                        if domain.get(bound) is None:
                            continue
                        limit = cast(domain.get(bound))
                        # The filter must accept the XML's bound, and clamp a value past it to it.
                        getattr(algorithm, setter)(limit)
                        self.assertEqual(getattr(algorithm, getter)(), limit,
                                         "%s.%s refuses the XML %s %s" % (class_name, prop.get("name"), bound, limit))
                        past = limit + beyond * max(1, abs(limit))
                        getattr(algorithm, setter)(past)
                        self.assertEqual(getattr(algorithm, getter)(), limit,
                                         "%s.%s: the XML %s is %s, the filter takes %s"
                                         % (class_name, prop.get("name"), bound, limit, getattr(algorithm, getter)()))
        self.assertGreater(checked, 40)


if __name__ == "__main__":
    unittest.main()
