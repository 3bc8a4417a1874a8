// Stages 1-2: a face model (72 points, FAPUs) and its 3D lift (thesis 2.2, 2.3, Algorithm 2.1).
//
//   face_model [FACE.xml]     the built-in default face when no file is given
#include <cstdio>
#include <exception>
#include <iostream>

#include <talkface/talkface.hpp>

int main(int argc, char** argv) {
    if (argc > 2) {
        std::cerr << "usage: face_model [FACE.xml]\n";
        return 2;
    }
    try {
        const talkface::FaceModel face =
            argc == 2 ? talkface::FaceModel::load(argv[1]) : talkface::FaceModel::default_face();
        std::printf("face \"%s\": %zu points, %zu FAPUs\n\n", face.name().c_str(),
                    talkface::FaceModel::kPointCount, talkface::FaceModel::kFapuCount);

        std::printf("FAPUs (pixels)\n");
        for (const std::string& name : talkface::FaceModel::fapu_names()) {
            std::printf("  %-10s %8.2f\n", name.c_str(), face.fapu(name));
        }

        const talkface::LiftedFace lifted = talkface::lift_face(face);
        std::printf("\nrotation origin O = (%.2f, %.2f), d = %.2f px\n\n", lifted.origin.x, lifted.origin.y,
                    lifted.d);
        std::printf("%-12s %9s %9s   %9s %9s %9s   %7s\n", "point", "image x", "image y", "local x", "local y",
                    "local z", "z / d");
        // The frontal projection puts every point, A .. S included, where the lift took it from.
        const talkface::ProjectedFace frontal = talkface::project_face(face, talkface::FaceState{});
        for (const talkface::LiftedPoint& point : lifted.points) {
            const talkface::Point2 image = frontal.point(point.id);
            const talkface::Point3& local = point.local;
            std::printf("%-12s %9.2f %9.2f   %9.2f %9.2f %9.2f   %7.3f\n", point.id.c_str(), image.x, image.y,
                        local.x, local.y, local.z, local.z / lifted.d);
        }
    } catch (const std::exception& error) {
        std::cerr << "face_model: error: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
