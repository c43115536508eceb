% The tilt controller's parameters (tilt_controller_r2022b): the balancing loop of the thesis' robot, its Kalman
% filter in the current-estimate form with a steady-state gain from `duet design kalman` (A, C, G and Q of
% apps/balbot/balbot.yaml, R = [1e-5 0; 0 0.00033]): the thesis' tilt variance of 0.8 deg^2 would leave the fixed-gain
% filter seconds to find the tilt the robot is held at (estimator eigenvalue 0.99998), this one 0.2 s (0.994).
Ts = 0.001;                        % s, the base period
kalman_A = [1 Ts; 0 1];            % tilt and tilt rate, one step
kalman_L = [0.005728086339372147, 0.000994271704841565; ...
            0.03281096625973752, 0.999930525062563];
P = 0.3;  I = 8;  D = 0.06;  N = 28.234;
target = 0;                        % deg
speed_gain = 4;                    % deg/(m/s)
position_gain = 2;                 % deg/m
stop_angle = 60;                   % deg
