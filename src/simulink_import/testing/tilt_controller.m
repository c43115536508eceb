% The tilt controller's parameters (tilt_controller_r2022b): the balancing loop of the thesis' robot, its Kalman
% filter in the current-estimate form with the steady-state gain `duet design kalman` gives for the robot's noise.
Ts = 0.001;                        % s, the base period
kalman_A = [1 Ts; 0 1];            % tilt and tilt rate, one step
kalman_L = [2.0309889762471297e-05, 0.0009999796893655844; ...
            4.124916218644528e-07, 0.9999633356094841];
P = 0.3;  I = 8;  D = 0.06;  N = 28.234;
target = 0;                        % deg
speed_gain = 4;                    % deg/(m/s)
position_gain = 2;                 % deg/m
stop_angle = 60;                   % deg
