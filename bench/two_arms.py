"""Two copies of a URDF side by side under one world link: every link and joint named with a
prefix (left_, right_), the roots fixed to the world 0.8 apart along y. A robot of twice the
links for the view's benchmarks (bench/view_robot_interactive.sh).
    /usr/bin/python3 bench/two_arms.py IN.urdf OUT.urdf
"""
import sys
import xml.etree.ElementTree as ET


def main(src, dst):
    arm = ET.parse(src).getroot()
    robot = ET.Element("robot", {"name": "two_" + arm.get("name", "arm")})
    ET.SubElement(robot, "link", {"name": "world"})
    children = {j.find("child").get("link") for j in arm.findall("joint")}
    roots = [l.get("name") for l in arm.findall("link") if l.get("name") not in children]
    for prefix, y in (("left_", 0.4), ("right_", -0.4)):
        for element in arm:
            if element.tag not in ("link", "joint"):
                continue
            copy = ET.fromstring(ET.tostring(element))
            copy.set("name", prefix + copy.get("name"))
            for tag in ("parent", "child"):
                node = copy.find(tag)
                if node is not None:
                    node.set("link", prefix + node.get("link"))
            mimic = copy.find("mimic")
            if mimic is not None:
                mimic.set("joint", prefix + mimic.get("joint"))
            robot.append(copy)
        for root in roots:
            joint = ET.SubElement(robot, "joint", {"name": prefix + "mount", "type": "fixed"})
            ET.SubElement(joint, "parent", {"link": "world"})
            ET.SubElement(joint, "child", {"link": prefix + root})
            ET.SubElement(joint, "origin", {"xyz": f"0 {y} 0", "rpy": "0 0 0"})
    ET.ElementTree(robot).write(dst, xml_declaration=True, encoding="utf-8")


if __name__ == "__main__":
    main(*sys.argv[1:3])
