use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = spher(radius = 0.1), law = rolling, gravity = 9.81)]
struct Misspelled;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radiu = 0.1), law = rolling, gravity = 9.81)]
struct UnknownKey;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = torus(radius = 0.1), law = rolling, gravity = 9.81)]
struct MissingTube;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = 0.1, law = rolling, gravity = 9.81)]
struct NotAForm;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(sphere(radius = 0.1), law = rolling, gravity = 9.81)]
struct SurfaceAsItem;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1, radius = 0.2), law = rolling, gravity = 9.81)]
struct TwoRadii;

#[derive(RigidBody)]
#[rigid(disk(mass = 1.0, radius = 0.1))]
#[contact(surface = disk_rim(radius = 0.1, axle = z), law = rolling, gravity = 9.81)]
struct AxleOnTheTable;

fn main() {}
