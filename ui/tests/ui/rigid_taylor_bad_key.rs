use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), taylor = 0)]
struct OrderZero;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), taylor = 2.5)]
struct NotAnInteger;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), taylor = 20, taylor = 10)]
struct Twice;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), tailor = 20)]
struct Misspelled;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), taylor)]
struct NoValue;

fn main() {}
