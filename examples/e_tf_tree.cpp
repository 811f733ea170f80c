// A small robot frame tree: world -> base -> sensor (and world -> landmark). A point measured by the sensor is
// expressed in the world frame and relative to a landmark through TfTree::tf(from, to).
// The program checks its own results and exits with 1 if any of them is wrong.
#include <iostream>
#include <string>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/StdLib.h"

namespace
{
    int failures = 0;

    void show(const std::string &what, const rtl::Vector3d &got, const rtl::Vector3d &expected)
    {
        const bool ok = rtl::Vector3d::distance(got, expected) < 1e-12;
        std::cout << what << got;
        if (!ok)
        {
            std::cout << "   <-- WRONG, expected " << expected;
            ++failures;
        }
        std::cout << "\n";
    }
}

int main()
{
    // A node's transformation maps coordinates in its parent's frame to coordinates in its own frame, and
    // tf(from, to) returns the chain mapping coordinates in `from` to coordinates in `to`. A pose (the frame's
    // placement in its parent, i.e. own frame -> parent frame) is therefore inserted inverted.
    const rtl::RigidTf3d basePose(rtl::C_PI_2d, rtl::Vector3d(0, 0, 1), rtl::Vector3d(2, 0, 0));   // base in world
    const rtl::RigidTf3d sensorPose(0.0, rtl::Vector3d(0, 0, 1), rtl::Vector3d(0.5, 0, 1));       // sensor on base
    const rtl::RigidTf3d landmarkPose(0.0, rtl::Vector3d(0, 0, 1), rtl::Vector3d(5, 5, 0));       // landmark in world

    rtl::TfTree<std::string, rtl::RigidTf3d> tree("world");
    tree.insert("base", basePose.inverted(), "world");
    tree.insert("sensor", sensorPose.inverted(), "base");
    tree.insert("landmark", landmarkPose.inverted(), "world");
    std::cout << tree;

    const rtl::Vector3d hit(1, 0, 0);   // a point 1 m in front of the sensor
    const auto sensorToWorld = tree.tf("sensor", "world");
    std::cout << "chain sensor->world has " << sensorToWorld.list().size() << " steps\n";
    failures += sensorToWorld.list().size() == 2 ? 0 : 1;
    show("hit in world:      ", sensorToWorld(hit), rtl::Vector3d(2, 1.5, 1));
    // Up to the common ancestor (world), then down to the landmark.
    show("hit in landmark:   ", tree.tf("sensor", "landmark")(hit), rtl::Vector3d(-3, -3.5, 1));
    // The squashed chain is one rigid transformation: the sensor's pose in the world.
    const rtl::RigidTf3d sensorInWorld = tree.tf("sensor", "world").squash();
    show("sensor in world:   ", sensorInWorld.trVec(), rtl::Vector3d(2, 0.5, 1));

    // Moving the base moves everything below it.
    tree["base"].tf() = rtl::RigidTf3d(rtl::C_PI_2d, rtl::Vector3d(0, 0, 1), rtl::Vector3d(3, 0, 0)).inverted();
    show("after moving base: ", tree.tf("sensor", "world")(hit), rtl::Vector3d(3, 1.5, 1));

    tree.erase("base");                                             // removes base and sensor
    std::cout << "frames left: " << tree.size() << "\n";
    failures += (tree.size() == 2 && !tree.contains("sensor")) ? 0 : 1;
    return failures == 0 ? 0 : 1;
}
