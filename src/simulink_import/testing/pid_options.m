% The variables of pid_options.mdl (test file of pid_options_test): the gains of its PID blocks and their output limit.
Kp = 1;       % proportional gain
Ki = 20;      % integral gain, 1/s: 0.2 a step of 10 ms at an error of 1
Kd = 0.05;    % derivative gain, s
Nf = 50;      % derivative filter coefficient, 1/s (N Ts = 0.5, a stable filter)
limit = 1.5;  % the output limit of "PID limited" and "PID clamped"
